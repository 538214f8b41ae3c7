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
