// The error at the seams of the point layouts measured apart from the rest (issue #25): pixels
// whose receiver lies within 2 texels of the plane where two views meet (a cube or tetrahedron
// face edge, the paraboloids' equator) against all other pixels, on street's lamp with each
// preset's defaults. Also checks the instrument: seamDistanceTexels against a hand-computed case.
#include "point/seams.h"
#include "point/street_truth.h"
#include "tests/assets_dir.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace sl {
namespace {

// Two perspective views along +x and +y from the origin, texel 0.01 at unit distance: a point at
// (2, 1.9, 0) reads the +x view, lies 0.1 / sqrt(2) from the seam plane x = y, and a texel there
// (2 along the axis) is 0.02 wide: 3.54 texels.
TEST(PointSeams, DistanceIsTheGapToTheSeamPlaneInTexels) {
  LightSpace space;
  space.views.clear();
  for (const glm::vec3& axis : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)}) {
    LightView v;
    v.view = glm::lookAt(glm::vec3(0.0f), axis, axis.y > 0.5f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0));
    v.perspective = true;
    v.texelWorldSize = 0.01f;
    space.views.push_back(v);
  }
  EXPECT_NEAR(seamDistanceTexels(space, glm::vec3(0.0f), {2.0f, 1.9f, 0.0f}), 0.1f / std::sqrt(2.0f) / 0.02f, 1e-3f);
  // (1, 2, 0) reads the +y view (2 along its axis): 1 / sqrt(2) from the seam, 35.4 texels.
  EXPECT_NEAR(seamDistanceTexels(space, glm::vec3(0.0f), {1.0f, 2.0f, 0.0f}), 1.0f / std::sqrt(2.0f) / 0.02f, 1e-3f);
  space.views.resize(1);
  EXPECT_TRUE(std::isinf(seamDistanceTexels(space, glm::vec3(0.0f), {1.0f, 0.0f, 0.0f})));
}

class PointSeamsGl : public ::testing::TestWithParam<std::string> {};

TEST_P(PointSeamsGl, SeamErrorIsMeasuredApartFromTheRest) {
  test::GlHarness h;
  const test::StreetTruth t = test::streetTruth(h, 320, 180);
  const ReferenceImage& reference = t.reference;
  Viewport vp(makeTechnique(GetParam()));
  test::renderFromCut(h, t.in, vp);
  const test::Frame f = test::readFrame(h.renderer, vp, 320, 180);
  long seam = 0, seamWrong = 0, rest = 0, restWrong = 0;
  for (size_t i = 0; i < reference.valid.size(); ++i) {
    if (!reference.valid[i] || f.position[4 * i + 3] < 0.5f) continue;
    const glm::vec3 p(f.position[4 * i], f.position[4 * i + 1], f.position[4 * i + 2]);
    const bool wrong = std::abs(f.visibility[2 * i] - reference.visibility[i]) > 30.0f / 255.0f;
    if (seamDistanceTexels(vp.lightSpace, t.scene.light.position, p) <= 2.0f) {
      ++seam;
      seamWrong += wrong;
    } else {
      ++rest;
      restWrong += wrong;
    }
  }
  const double seamPct = 100.0 * seamWrong / std::max(seam, 1L), restPct = 100.0 * restWrong / std::max(rest, 1L);
  std::printf("%s: seam pixels %ld, wrong %.3f %%; other pixels %ld, wrong %.3f %%\n", GetParam().c_str(), seam,
              seamPct, rest, restPct);
  EXPECT_GT(seam, 20) << "street's default view crosses the seams";
  EXPECT_LE(seamPct, std::max(2.0, 5.0 * restPct)) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(PointSeams, PointSeamsGl,
                         ::testing::Values("cube", "cube-pcf", "tetrahedron", "tetrahedron-pcf", "dual-paraboloid",
                                           "dual-paraboloid-pcf"),
                         test::presetTestName);

}  // namespace
}  // namespace sl
