// technique.layout: any preset's representation and accumulation over any layout, chosen like a
// parameter (makeTechnique, --set, sweeps, the panel), and every pairing renders finite and error
// free on the GPU, or says in its status why it falls back (tiny frames: this is about wiring).
#include "bench/bench.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <gtest/gtest.h>

namespace sl {
namespace {

TEST(LayoutChoice, AnOverridePutsThePresetOverThatLayoutWithItsParameters) {
  const Technique t = makeTechnique("pixel-correct", {"technique.layout=tsm", "tsm.focus_share=0.7"});
  EXPECT_EQ(t.layout->id(), "tsm");
  EXPECT_EQ(t.accumulation->id(), "pixel-correct");
  EXPECT_EQ(t.params.choice(kLayoutParam), "tsm");
  EXPECT_FLOAT_EQ(t.params.f("tsm.focus_share"), 0.7f);
  EXPECT_FALSE(t.params.has("lispsm.n"));
  // The preset's own layout by default, and its overrides of that layout's parameters are kept.
  EXPECT_EQ(makeTechnique("pcf").params.choice(kLayoutParam), "focused");
  EXPECT_EQ(makeTechnique("face-partitioned").params.f("bias.slope"), 2.0f);
  // Over another layout a preset's layout-only overrides are dropped, the common ones kept.
  EXPECT_EQ(makeTechnique("face-partitioned", {"technique.layout=focused"}).params.f("bias.slope"), 2.0f);
  try {
    makeTechnique("pcf", {"technique.layout=nope"});
    ADD_FAILURE() << "no error for an unknown layout";
  } catch (const ParamError& e) {
    EXPECT_NE(std::string(e.what()).find("cascaded"), std::string::npos) << e.what();  // lists the layouts
  }
}

TEST(LayoutChoice, RecomposedCarriesTheSharedValuesOver) {
  Technique t = makeTechnique("vsm", {"filter.width=7", "shadowmap.size=512"});
  t.params.setFromString(kLayoutParam, "cascaded");
  const Technique r = recomposed(t);
  EXPECT_EQ(r.layout->id(), "cascaded");
  EXPECT_EQ(r.representation->id(), t.representation->id());
  EXPECT_EQ(r.params.i("filter.width"), 7);
  EXPECT_EQ(r.params.i("shadowmap.size"), 512);
  EXPECT_TRUE(r.params.has("cascades.count"));
}

TEST(LayoutChoice, BenchSweepsTheLayoutOfOnePreset) {
  BenchOptions o;
  o.techniques = {"pcf"};
  o.sweeps = {"technique.layout=focused,lispsm,cascaded"};
  o.sets = {"pcf.kernel=5"};
  const auto plan = planBench(o);
  ASSERT_EQ(plan.size(), 3u);
  EXPECT_EQ(plan[1].technique.layout->id(), "lispsm");
  EXPECT_EQ(plan[2].technique.layout->id(), "cascaded");
  EXPECT_EQ(plan[2].technique.params.i("pcf.kernel"), 5);
  // --set technique.layout first, then that layout's own keys.
  BenchOptions s;
  s.techniques = {"standard"};
  s.sets = {"technique.layout=cascaded", "cascades.count=2"};
  EXPECT_EQ(planBench(s).front().technique.params.i("cascades.count"), 2);
}

// Every layout (one test each) under representative representations and accumulations: finite,
// in [0, 1], no shader or GL error.
class LayoutChoiceGl : public ::testing::TestWithParam<std::string> {};

TEST_P(LayoutChoiceGl, UnderEveryFamilyRendersFinite) {
  test::GlHarness h;
  const Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  for (const char* preset : {"standard", "pcf", "vsm", "convolution", "msm", "pcss", "pixel-correct", "alias-free",
                             "silhouette", "forward"}) {
    {
      SCOPED_TRACE(std::string(preset) + " over " + GetParam());
      Viewport vp(makeTechnique(preset, {"technique.layout=" + GetParam(), "shadowmap.size=256"}));
      for (int f = 0; f < 2; ++f) {
        FrameInput in;
        in.camera = scene.cameras.front();
        in.width = 48;
        in.height = 27;
        in.cut = f == 0;
        h.renderer.render(in, {&vp});
      }
      const test::Frame frame = test::readFrame(h.renderer, vp, 48, 27);
      EXPECT_EQ(frame.nonfinite(), 0);
      for (size_t i = 0; i < frame.visibility.size(); i += 2)
        if (frame.visibility[i] < 0.0f || frame.visibility[i] > 1.0f) {
          ADD_FAILURE() << "visibility " << frame.visibility[i];
          break;
        }
    }
  }
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

std::vector<std::string> layoutIds() {
  std::vector<std::string> ids;
  for (const auto& l : allLayouts()) ids.push_back(l->id());
  return ids;
}

INSTANTIATE_TEST_SUITE_P(Layouts, LayoutChoiceGl, ::testing::ValuesIn(layoutIds()), [](const auto& info) {
  std::string name = info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

}  // namespace
}  // namespace sl
