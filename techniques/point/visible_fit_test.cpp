// The corners a face's fit is cropped to when point.fit_visible measured its pixels.
#include "point/visible_fit.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace sl {
namespace {

// The tangent coordinates (x/-z, y/-z) of a point in `view`.
glm::vec2 tangentOf(const glm::mat4& view, const glm::vec3& world) {
  const glm::vec3 v(view * glm::vec4(world, 1.0f));
  return glm::vec2(v) / -v.z;
}

TEST(VisibleFit, CornersHoldThePixelsRectangleWithItsMarginAndNoMore) {
  const glm::mat4 view = glm::rotate(glm::mat4(1.0f), 0.3f, glm::vec3(0, 0, 1)) *
                         glm::lookAt(glm::vec3(1, 2, 3), glm::vec3(1, 1, 3), glm::vec3(0, 0, 1));
  ViewPixelBounds b;
  b.valid = true;
  b.lo = {-0.4f, 0.1f};
  b.hi = {0.2f, 0.3f};
  b.nearest = 0.5f;
  b.farthest = 7.0f;
  const int size = 200;  // 4 texels of 200: 2 %; and 2 % more: 0.6 * 0.04 = 0.024 on each side
  const std::vector<glm::vec3> corners = pixelBoundsCorners(b, view, size);
  ASSERT_EQ(corners.size(), 8u);
  glm::vec2 lo(1e9f), hi(-1e9f);
  float nearest = 1e9f, farthest = 0.0f;
  for (const glm::vec3& c : corners) {
    lo = glm::min(lo, tangentOf(view, c));
    hi = glm::max(hi, tangentOf(view, c));
    const float z = -(view * glm::vec4(c, 1.0f)).z;
    nearest = std::min(nearest, z);
    farthest = std::max(farthest, z);
  }
  EXPECT_NEAR(lo.x, -0.424f, 1e-4f);
  EXPECT_NEAR(lo.y, 0.076f, 1e-4f);
  EXPECT_NEAR(hi.x, 0.224f, 1e-4f);
  EXPECT_NEAR(hi.y, 0.324f, 1e-4f);
  EXPECT_NEAR(nearest, 0.5f, 1e-4f);
  EXPECT_NEAR(farthest, 7.0f, 1e-3f);
}

}  // namespace
}  // namespace sl
