// Optimized PCF on llvmpipe: its 4, 9 or 16 bilinear taps give the tent filter they stand for,
// texel by texel ((N + 1)² single-texel compares), under every layout; and the filter softens
// edges (some pixels between 0 and 1) where the nearest test has none.
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

}  // namespace
}  // namespace sl
