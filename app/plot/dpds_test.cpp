// The dp/ds curves (no GPU): a focused map's texels are constant, so against pixels that grow
// with depth the ratio falls as 1/z; warps flatten it, cascades turn it into a saw, the ideal
// logarithmic curve is flat; the SVG has a curve and a legend entry per technique.
#include "gl/shader_library.h"
#include "plot/dpds.h"
#include "layouts/layout_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace sl {
namespace {

TEST(Dpds, FocusedFallsAsOneOverDepthWarpsFlattenCascadesSawIdealIsFlat) {
  Scene scene = loadScene("columns", defaultAssetsDir());
  const auto curves = dpdsCurves(scene, scene.cameras.front(), 1280, 720,
                                 {"standard", "lispsm", "psm", "cascaded:cascades.count=4"}, 64);
  ASSERT_EQ(curves.size(), 5u);
  const DpdsCurve& focused = curves[0];
  // Log-log slope between two depths well inside the map.
  const size_t a = 8, b = 56;
  ASSERT_TRUE(std::isfinite(focused.ratio[a]) && std::isfinite(focused.ratio[b]));
  const float slope = std::log(focused.ratio[b] / focused.ratio[a]) / std::log(focused.depth[b] / focused.depth[a]);
  EXPECT_NEAR(slope, -1.0f, 0.05f);
  EXPECT_LT(test::dpdsSpread(curves[1]), 0.6f * test::dpdsSpread(focused));  // LiSPSM
  EXPECT_LT(test::dpdsSpread(curves[2]), 0.6f * test::dpdsSpread(focused));  // PSM
  int jumps = 0;  // cascades: the ratio falls within a split and jumps up at each border
  for (size_t i = 1; i < curves[3].ratio.size(); ++i) jumps += curves[3].ratio[i] > 1.2f * curves[3].ratio[i - 1];
  EXPECT_EQ(jumps, 3);
  EXPECT_LT(test::dpdsSpread(curves[4]), 1e-4f);
  const std::string svg = plotSvg(dpdsPlot(curves, "test"));
  for (const auto& c : curves) EXPECT_NE(svg.find(">" + c.label + "<"), std::string::npos) << c.label;
  size_t lines = 0;  // a curve leaving the map is drawn as several strokes
  for (size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1)) ++lines;
  EXPECT_GE(lines, curves.size());
}

}  // namespace
}  // namespace sl
