// point.fit_visible: each face fitted to the pixels that read it (a reduction of the G-buffer)
// instead of to the view frustum's part of the scene, each axis on its own. On street's default
// camera, which sees the lamp, the frustum fit leaves the faces almost whole (1.00x for the cube,
// 1.06x for the tetrahedron); the pixels that read a face fill less of it along at least one axis,
// so its texels are smaller where it matters. One test per preset.
#include "point/street_truth_test_util.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace sl {
namespace {

class FitVisibleGl : public ::testing::TestWithParam<std::string> {};

TEST_P(FitVisibleGl, FacesFittedToThePixelsGetFewerWrongPixels) {
  test::GlHarness h;
  test::SceneTruth t = test::sceneTruth(h, "street", 192, 108);
  double wrong[2] = {0, 0};
  std::string status[2];
  for (int fit = 0; fit < 2; ++fit) {
    // The preset's texels: at a few hundred texels a face the error follows where the snapped
    // texel grid happens to fall more than the window's size.
    Viewport vp(makeTechnique(GetParam(), {fit ? "point.fit_visible=on" : "point.fit_visible=off"}));
    test::renderFromCut(h, t.in, vp);
    const ErrorMetrics m = viewportErrorMetrics(vp, t.reference);
    wrong[fit] = m.wrongPixelPct;
    status[fit] = vp.status();
    EXPECT_EQ(m.nonfinite, 0);
  }
  // Measured: cube 0.031 % against 0.228 %, tetrahedron 0.093 % against 0.342 %.
  EXPECT_LT(wrong[1], 0.5 * wrong[0]) << "fitted to pixels " << wrong[1] << " %, to the frustum " << wrong[0] << " %\n"
                                      << status[1] << "\n"
                                      << status[0];
  EXPECT_NE(status[1], status[0]);
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

INSTANTIATE_TEST_SUITE_P(Faces, FitVisibleGl, ::testing::Values("cube", "tetrahedron"), test::presetTestName);

// A face that no visible pixel reads is not drawn, though the frustum reaches into it: street's
// `away` camera looks along the street away from the lamp.
TEST(FitVisibleFacesGl, FacesNoPixelReadsAreNotDrawn) {
  test::GlHarness h;
  test::SceneTruth t = test::sceneTruth(h, "street", 96, 54);
  const auto cam =
      std::find_if(t.scene.cameras.begin(), t.scene.cameras.end(), [](const Camera& c) { return c.name == "away"; });
  ASSERT_NE(cam, t.scene.cameras.end());
  t.in.camera = *cam;
  int drawn[2] = {0, 0};
  for (int fit = 0; fit < 2; ++fit) {
    Viewport vp(makeTechnique("cube", {"shadowmap.size=128", fit ? "point.fit_visible=on" : "point.fit_visible=off"}));
    test::renderFromCut(h, t.in, vp);
    ASSERT_EQ(std::sscanf(vp.status().c_str(), "cube: %d of 6", &drawn[fit]), 1) << vp.status();
  }
  EXPECT_LT(drawn[1], drawn[0]);  // measured 2 against 3
  EXPECT_GE(drawn[1], 1);
}

}  // namespace
}  // namespace sl
