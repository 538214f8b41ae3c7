// point.fit_visible: each face fitted to the pixels that read it (a reduction of the G-buffer)
// instead of to the view frustum's part of the scene. On street's default camera, which sees the
// lamp, the frustum fit leaves the tetrahedron's faces almost whole (1.06x); the visible pixels
// fill less of them, so the fitted faces have smaller texels where it matters.
#include "tests/scene_truth_test_util.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace sl {
namespace {

TEST(FitVisibleGl, TetrahedronFacesFittedToThePixelsGetFewerWrongPixels) {
  test::GlHarness h;
  test::SceneTruth t = test::sceneTruth(h, "street", 192, 108);
  double wrong[2] = {0, 0};
  std::string status[2];
  for (int fit = 0; fit < 2; ++fit) {
    // The preset's texels (4 x 1254^2): at a few hundred texels a face the error follows where
    // the snapped texel grid happens to fall, not the window's size.
    Viewport vp(makeTechnique("tetrahedron", {fit ? "point.fit_visible=on" : "point.fit_visible=off"}));
    test::renderFromCut(h, t.in, vp);
    const ErrorMetrics m = viewportErrorMetrics(vp, t.reference);
    wrong[fit] = m.wrongPixelPct;
    status[fit] = vp.status();
    EXPECT_EQ(m.nonfinite, 0);
  }
  // Measured 0.166 % against 0.342 % (the status: windows 1.09-1.26x against 1.06x the face).
  EXPECT_LT(wrong[1], 0.7 * wrong[0]) << "fitted to pixels " << wrong[1] << " %, to the frustum " << wrong[0] << " %\n"
                                      << status[1] << "\n"
                                      << status[0];
  EXPECT_NE(status[1], status[0]);
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

// A face that no visible pixel reads is not drawn, though the frustum reaches into it: street's
// `away` camera looks along the street away from the lamp.
TEST(FitVisibleGl, FacesNoPixelReadsAreNotDrawn) {
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
