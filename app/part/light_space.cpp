#include "part/light_space.h"

#include <algorithm>
#include <cmath>

namespace sl {

bool LightSpace::perspective() const {
  for (const LightView& v : views)
    if (v.perspective) return true;
  return false;
}

int LightSpace::layerOf(size_t view) const {
  const int layer = view < views.size() ? views[view].layer : -1;
  return layer >= 0 ? layer : static_cast<int>(view);
}

int LightSpace::layerCount() const {
  int count = 0;
  for (size_t v = 0; v < views.size(); ++v) count = std::max(count, layerOf(v) + 1);
  return std::max(count, 1);
}

bool LightSpace::packed() const {
  return std::any_of(views.begin(), views.end(), [](const LightView& v) { return v.packedTriangle >= 0; });
}

bool LightSpace::sharesLayers() const { return layerCount() < static_cast<int>(views.size()); }

glm::mat4 squareOntoRect(const glm::ivec4& rect, float side, int layerSize) {
  glm::mat4 place(1.0f);
  place[0][0] = place[1][1] = side / float(layerSize);
  place[3][0] = (float(rect.x) + 0.5f * float(rect.z)) / float(layerSize) * 2.0f - 1.0f;
  place[3][1] = (float(rect.y) + 0.5f * float(rect.w)) / float(layerSize) * 2.0f - 1.0f;
  return place;
}

bool placeInAtlasRegion(LightSpace& space, const glm::ivec4& region, int atlasSize) {
  if (region.z <= 0 || region.z != space.size || region.x < 0 || region.y < 0 || region.x + region.z > atlasSize ||
      region.y + region.w > atlasSize || space.layerCount() != 1)
    return false;
  for (const LightView& v : space.views)
    if (v.projection != LightView::Projection::Matrix) return false;
  const glm::mat4 place = squareOntoRect(region, float(region.z), atlasSize);
  for (LightView& v : space.views) {
    v.proj = place * v.proj;
    v.viewProj = v.proj * v.view;
    v.layer = 0;
    // Several views in the layer: each in its rectangle (one without is not drawn: no room).
    if (v.atlasRect.z > 0)
      v.atlasRect += glm::ivec4(region.x, region.y, 0, 0);
    else if (space.views.size() == 1 || v.packedTriangle >= 0)
      v.atlasRect = region;
    for (glm::vec2& uv : v.receiverHull) uv = (glm::vec2(region.x, region.y) + uv * float(region.z)) / float(atlasSize);
  }
  space.size = atlasSize;
  space.atlasPlacement = glm::vec3(place[0][0], place[3][0], place[3][1]);
  return true;
}

float logWarp(float t, float delta) {
  if (!(delta > 0.0f) || delta >= kNoWarpDelta) return t;
  const double x = std::max(double(t) / delta, -0.999);  // the pole at t = -δ
  return float(std::log1p(x) / std::log1p(1.0 / delta));
}

glm::vec4 lightViewClip(const LightView& view, const glm::vec3& world) {
  if (view.projection == LightView::Projection::Paraboloid) {
    const glm::vec3 v(view.view * glm::vec4(world, 1.0f));
    const float r = glm::length(v);
    if (!(r > 1e-20f)) return glm::vec4(0.0f);  // the light itself (or NaN): w = 0, not in the map
    const glm::vec3 d = v / r;
    const glm::vec2 disk = paraboloidDiskImage(d);
    const glm::vec2 uv =
        (disk - glm::vec2(view.paraboloidWindow)) * glm::vec2(view.paraboloidWindow.z, view.paraboloidWindow.w);
    const float depth = (r - view.nearPlane) / (view.farPlane - view.nearPlane);
    return {uv, depth * 2.0f - 1.0f, 1.0f};
  }
  glm::vec4 c = view.viewProj * glm::vec4(world, 1.0f);
  if (view.logDelta > 0.0f) {
    c.w = std::max(c.w, 1e-3f);  // as layouts/single_matrix.glsl: behind the pole is off the map
    c.y = (2.0f * logWarp(c.y * 0.5f + 0.5f, view.logDelta) - 1.0f) * c.w;
  }
  return c;
}

}  // namespace sl
