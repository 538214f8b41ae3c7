#include "point/seams.h"

#include <cmath>
#include <limits>

namespace sl {

namespace {

glm::vec3 viewAxis(const LightView& v) { return -glm::vec3(v.view[0][2], v.view[1][2], v.view[2][2]); }

// World size of one texel of `v` across the ray at p: perspective faces scale with the distance
// along the axis; a paraboloid's texel turns 2 * 1.05 / (size * zoom) * (1 + cos theta) radians
// (layouts/dual_paraboloid.glsl, layoutTexelWorldSize; zoom: its fitted window's).
float texelAt(const LightView& v, const glm::vec3& toPoint, int size) {
  const float along = glm::dot(toPoint, viewAxis(v));
  if (v.projection == LightView::Projection::Paraboloid) {
    const float r = glm::length(toPoint);
    return r * 2.0f * kParaboloidWindow / (float(size) * v.paraboloidWindow.z) * (1.0f + along / std::max(r, 1e-20f));
  }
  return v.perspective ? v.texelWorldSize * along : v.texelWorldSize;
}

}  // namespace

float seamDistanceTexels(const LightSpace& space, const glm::vec3& lightPosition, const glm::vec3& p) {
  const size_t n = space.views.size();
  if (n < 2) return std::numeric_limits<float>::infinity();
  const glm::vec3 d = p - lightPosition;
  size_t own = 0;
  for (size_t i = 1; i < n; ++i)
    if (glm::dot(d, viewAxis(space.views[i])) > glm::dot(d, viewAxis(space.views[own]))) own = i;
  float nearest = std::numeric_limits<float>::infinity();
  const glm::vec3 a = viewAxis(space.views[own]);
  for (size_t j = 0; j < n; ++j) {
    if (j == own) continue;
    const glm::vec3 normal = a - viewAxis(space.views[j]);  // the seam: dot(d, normal) = 0
    const float len = glm::length(normal);
    if (len > 1e-6f) nearest = std::min(nearest, std::abs(glm::dot(d, normal)) / len);
  }
  return nearest / std::max(texelAt(space.views[own], d, space.size), 1e-20f);
}

}  // namespace sl
