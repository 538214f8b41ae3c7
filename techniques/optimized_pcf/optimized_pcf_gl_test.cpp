// Optimized PCF on llvmpipe: its 4, 9 or 16 bilinear taps give the tent filter they stand for,
// texel by texel ((N + 1)² single-texel compares), under every layout; and the filter softens
// edges (some pixels between 0 and 1) where the nearest test has none. Under pixel-correct
// accumulation its tests one texel beside a lookup (representationSameBeside, the history's
// rejection rule) decide as the generic four lookups do.
#include "tests/gl_test_util.h"
#include "technique.h"

#include <algorithm>
#include <cmath>

namespace sl {
namespace {

// Visibility of `preset` over `layout` with `sets`, one frame of 64 x 36 on `basic`.
std::vector<float> optimizedPcfVisibility(test::GlHarness& h, const Scene& scene, const std::string& layout,
                                          std::vector<std::string> sets) {
  sets.push_back("shadowmap.size=256");
  sets.push_back(std::string(kLayoutParam) + "=" + layout);
  if (layout == "logpsm") sets.push_back("logpsm.perspective=off");  // minutes under ASan; tested in layouts/
  Viewport vp(makeTechnique("optimized-pcf", sets));
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 64;
  in.height = 36;
  in.cut = true;
  h.renderer.render(in, {&vp});
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  return test::readFrame(h.renderer, vp, in.width, in.height).visibilityChannel();
}

class OptimizedPcfUnder : public ::testing::TestWithParam<std::string> {};

TEST_P(OptimizedPcfUnder, TapsReproduceTheTentTexelByTexel) {
  test::GlHarness h;
  const Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  for (const char* kernel : {"3", "5", "7"}) {
    const std::string k = std::string("pcf.kernel=") + kernel;
    const std::vector<float> taps = optimizedPcfVisibility(h, scene, GetParam(), {k});
    const std::vector<float> texels = optimizedPcfVisibility(h, scene, GetParam(), {k, "pcf.evaluate=every-texel"});
    ASSERT_EQ(taps.size(), texels.size());
    double worst = 0, sum = 0;
    int soft = 0;
    for (size_t i = 0; i < taps.size(); ++i) {
      ASSERT_TRUE(std::isfinite(taps[i])) << kernel << " pixel " << i;
      const double d = std::abs(double(taps[i]) - texels[i]);
      worst = std::max(worst, d);
      sum += d;
      soft += taps[i] > 0.02f && taps[i] < 0.98f;
    }
    // The hardware blends compares with its own weight precision (8 bits on llvmpipe) and the
    // visibility target is 16-bit float: agreement to 1/50 at every pixel, far closer on average.
    EXPECT_LE(worst, 0.02) << GetParam() << " kernel " << kernel;
    EXPECT_LE(sum / double(taps.size()), 0.002) << GetParam() << " kernel " << kernel;
    EXPECT_GT(soft, 0) << GetParam() << " kernel " << kernel << ": a tent filter leaves no soft pixel";
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

std::vector<std::string> everyLayout() {
  std::vector<std::string> ids;
  for (const Layout* l : allLayouts()) ids.push_back(l->id());
  return ids;
}

INSTANTIATE_TEST_SUITE_P(Layouts, OptimizedPcfUnder, ::testing::ValuesIn(everyLayout()), [](const auto& info) {
  std::string name = info.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
});

// The accumulated visibility of pixel-correct-optimized-pcf with `sets` after `frames` frames of
// `moving` (the box swings through the light), looking down on the box and its shadow.
std::vector<float> movingPixelCorrectVisibility(test::GlHarness& h, const Scene& scene, std::vector<std::string> sets,
                                                int frames) {
  sets.push_back("shadowmap.size=512");
  Viewport vp(makeTechnique("pixel-correct-optimized-pcf", sets));
  FrameInput in;
  in.camera = scene.cameras.front();
  in.camera.position = glm::vec3(1.0f, 6.0f, 6.0f);
  in.camera.target = glm::vec3(0.5f, 0.0f, 0.5f);
  in.width = 160;
  in.height = 90;
  for (int f = 0; f < frames; ++f) {
    in.time = 1.0 + f / 30.0;
    h.renderer.render(in, {&vp});
  }
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  return test::readFrame(h.renderer, vp, in.width, in.height).visibilityChannel();
}

int pixelsApart(const std::vector<float>& a, const std::vector<float>& b, float by) {
  int n = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) n += !(std::abs(a[i] - b[i]) <= by);
  return n;
}

// The rejection's neighbour test from the taps' own set-up (representationSameBeside) gives the
// accumulated images that the generic test (four tent lookups, texel by texel) gives, and the
// test matters there: without it the moving shadow's history is kept in other pixels.
TEST(OptimizedPcfPixelCorrect, NeighbourTestFromTheTapsDecidesAsTheGenericOne) {
  test::GlHarness h;
  const Scene scene = loadScene("moving", defaultAssetsDir());
  h.renderer.setScene(scene);
  const int frames = 24;
  const std::vector<float> taps = movingPixelCorrectVisibility(h, scene, {}, frames);
  const std::vector<float> texels = movingPixelCorrectVisibility(h, scene, {"pcf.evaluate=every-texel"}, frames);
  const std::vector<float> without = movingPixelCorrectVisibility(h, scene, {"pc.reject_neighbours=off"}, frames);
  ASSERT_EQ(taps.size(), texels.size());
  const int apart = pixelsApart(taps, texels, 0.1f), changed = pixelsApart(taps, without, 0.1f);
  std::printf(
      "[optimized-pcf pixel-correct] moving 160x90, %d frames: taps vs texel by texel %d px apart by > 0.1, "
      "vs without the neighbour test %d\n",
      frames, apart, changed);
  // The two evaluate the same tents up to the hardware's 8-bit blend weights: a pixel whose
  // decision sits on the threshold may go either way, no more than a few.
  EXPECT_LE(apart, static_cast<int>(taps.size() / 200)) << "of " << taps.size();
  EXPECT_GE(changed, 10) << "the neighbour test changed no pixel: the case does not exercise it";
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace
}  // namespace sl
