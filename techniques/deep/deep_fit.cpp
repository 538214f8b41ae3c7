#include "deep/deep_fit.h"

#include "scene/scene_effects.h"

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

Bounds semiTransparentBounds(const Scene& scene, double time) {
  Bounds b;
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    if (!instanceSemiTransparent(scene, i)) continue;
    const Bounds ib = scene.instanceBoundsAt(i, time);
    if (!ib.empty()) b.add(ib.min), b.add(ib.max);
  }
  for (const Volume& v : scene.volumes) {
    const glm::vec3 h = v.shape == Volume::Shape::Sphere ? glm::vec3(v.halfSize.x) : v.halfSize;
    b.add(v.center - h);
    b.add(v.center + h);
  }
  return b;
}

const DeepWindow kWholeMap{};

}  // namespace

DeepWindow deepFitWindow(const Scene& scene, double time, const LightView& view, int deepSize, int maxMagnify) {
  const Bounds b = semiTransparentBounds(scene, time);
  if (b.empty() || view.projection != LightView::Projection::Matrix) return kWholeMap;
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                      (corner & 4) ? b.max.z : b.min.z);
    const glm::vec4 clip = view.viewProj * glm::vec4(p, 1.0f);
    if (!(clip.w > 1e-6f)) return kWholeMap;  // behind a perspective light: no finite window
    const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return kWholeMap;
    lo = glm::min(lo, uv);
    hi = glm::max(hi, uv);
  }
  const float pad = 2.0f / static_cast<float>(std::max(deepSize, 1));
  lo = glm::clamp(lo - pad, 0.0f, 1.0f);
  hi = glm::clamp(hi + pad, 0.0f, 1.0f);
  if (!(hi.x > lo.x && hi.y > lo.y)) return kWholeMap;  // outside this view: nothing to store
  // Integer viewport: width = deepSize / size, x = -origin * width (rounded outward).
  const float minSize = 1.0f / static_cast<float>(std::max(maxMagnify, 1));
  DeepWindow w;
  for (int axis = 0; axis < 2; ++axis) {
    const float size = std::max(hi[axis] - lo[axis], minSize);
    const float pixels = std::floor(static_cast<float>(deepSize) / size);  // viewport extent
    const float offset = std::floor(lo[axis] * pixels);                    // -viewport origin
    w.size[axis] = static_cast<float>(deepSize) / pixels;
    w.origin[axis] = offset / pixels;
  }
  return w;
}

glm::ivec4 deepViewport(const DeepWindow& window, int deepSize) {
  const glm::vec2 extent = glm::round(glm::vec2(static_cast<float>(deepSize)) / window.size);
  const glm::vec2 origin = glm::round(-window.origin * extent);
  return {static_cast<int>(origin.x), static_cast<int>(origin.y), static_cast<int>(extent.x),
          static_cast<int>(extent.y)};
}

}  // namespace sl
