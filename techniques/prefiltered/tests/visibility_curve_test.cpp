// The visibility-versus-receiver-depth curves of `shadowlab plot`: Cantelli's one-tailed bound
// must lie above the true lit fraction of the same box at every receiver depth, and the
// command must write one curve per technique plus the true one.
#include "prefiltered/visibility_curve.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sl {
namespace {

TEST(VisibilityCurve, ChebyshevBoundsTheTrueLitFractionFromAbove) {
  test::GlHarness h;
  Scene scene = loadScene("overlap", defaultAssetsDir());
  h.renderer.setScene(scene);
  Viewport vp(makeTechnique("vsm", {"shadowmap.size=256", "filter.width=9"}));
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 64;
  in.height = 36;
  h.renderer.render(in, {&vp});
  const auto& state = dynamic_cast<const MomentMapState&>(*vp.representation);
  int checked = 0;
  // Texel centres (the bilinear lookup then reads exactly the box the true curve counts) along
  // a row through the plates' shadows, where the box holds two or three depths.
  for (int tx = 40; tx < 216; tx += 8) {
    const glm::vec3 uv((tx + 0.5f) / 256.0f, 128.5f / 256.0f, 0.0f);
    const std::vector<float> bound = reconstructedCurve(h.shaders, vp.technique, state, uv, 256);
    const std::vector<float> truth = trueCurve(*state.depthTexture(), uv, 9, 256);
    ASSERT_EQ(bound.size(), truth.size());
    for (size_t i = 0; i < bound.size(); ++i) {
      EXPECT_GE(bound[i], truth[i] - 1e-4f) << "texel " << tx << " depth " << i / 255.0;
      EXPECT_TRUE(i == 0 || truth[i] <= truth[i - 1]);
    }
    checked += truth.front() != truth.back() ? 1 : 0;
  }
  EXPECT_GT(checked, 3) << "too few texels with an occluder in the box";
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(VisibilityCurve, PlotCommandWritesOneCurvePerTechniqueAndTheTruth) {
  const std::string out = ::testing::TempDir() + "plot_test.svg";
  std::remove(out.c_str());
  const std::string cmd =
      std::string(SHADOWLAB_BINARY) +
      " plot --scene overlap --techniques vsm,ewgf,convolution --set shadowmap.size=256 --size 160x90 --out " + out +
      " > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::stringstream s;
  s << std::ifstream(out).rdbuf();
  const std::string svg = s.str();
  size_t lines = 0;
  for (size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1)) ++lines;
  EXPECT_EQ(lines, 4u);
  EXPECT_NE(svg.find(">ewgf<"), std::string::npos);
  const std::string bad =
      std::string(SHADOWLAB_BINARY) + " plot --scene overlap --techniques pcf --out " + out + " > /dev/null 2>&1";
  EXPECT_NE(std::system(bad.c_str()), 0) << "a technique that stores no moments must be refused";
}

// The explorer's twin (hold V, or --visibility-plot): the window runs with it pinned over a
// pre-filtered viewport and exits cleanly.
TEST(VisibilityCurve, ExplorerDrawsThePinnedPlot) {
  if (std::system("command -v xvfb-run > /dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not on PATH";
  const std::string shot = ::testing::TempDir() + "explorer_plot.png";
  std::remove(shot.c_str());
  const std::string cmd = "timeout 240 xvfb-run -a -s \"-screen 0 1280x800x24\" " + std::string(SHADOWLAB_BINARY) +
                          " --scene overlap --technique vsm --set shadowmap.size=256 --visibility-plot --frames 3"
                          " --screenshot-on-exit " +
                          shot + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  EXPECT_TRUE(std::ifstream(shot).good());
}

}  // namespace
}  // namespace sl
