// Test helper: whether a point lies in a convex polygon (blur_spans_test, moment_map_test).
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace sl::test {

// True where p lies in the counter-clockwise convex polygon (its edges included, within eps).
inline bool insideHull(const std::vector<glm::vec2>& hull, glm::vec2 p, float eps = 0.0f) {
  for (size_t i = 0; i < hull.size(); ++i) {
    const glm::vec2 a = hull[i], b = hull[(i + 1) % hull.size()];
    if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < -eps * glm::length(b - a)) return false;
  }
  return true;
}

}  // namespace sl::test
