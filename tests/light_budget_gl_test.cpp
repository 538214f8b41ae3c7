// The renderer's budget across several lights (render/light_budget.h, Renderer::budgetLightMaps):
// a light whose range holds no visible point draws nothing and changes no pixel; a texel budget
// shrinks the maps by footprint and keeps every light near its reference; a budget that holds
// every map at full size changes nothing.
#include "tests/assets_dir.h"
#include "tests/gl_test_util.h"
#include "tests/scene_truth_test_util.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <unistd.h>

namespace sl {
namespace {

// A lamp over a box at the origin, seen from above, and (with `far`) a second lamp with a box of
// its own 20 m away, out of the camera's view and reaching 3 m.
Scene lampsScene(bool far) {
  const std::string lights = std::string(R"({"type":"point","position":[0.5,3,0.5],"range":8})") +
                             (far ? R"(,{"type":"point","position":[20,3,20],"range":3})" : "");
  return loadScene(
      test::writeTempFile("budget_lamps_" + std::to_string(far) + "_" + std::to_string(::getpid()) + ".json",
                          R"({"objects":[{"name":"ground","shape":"plane","size":[50,50]},
      {"name":"box","shape":"box","size":[1,1,1],"transform":{"translate":[0,0.5,0]}},
      {"name":"far-box","shape":"box","size":[1,1,1],"transform":{"translate":[20,0.5,19]}}],
      "lights":[)" + lights + R"(],
      "cameras":[{"name":"top","position":[0,9,3],"target":[0,0,0],"fov_deg":50},
                 {"name":"both","position":[10,30,10.5],"target":[10,0,10],"fov_deg":70}]})"),
      test::kAssets);
}

std::vector<unsigned char> colourOf(test::GlHarness& h, const Scene& scene, const std::string& camera, Viewport& vp) {
  h.renderer.setScene(scene);
  FrameInput in;
  in.camera = *scene.findCamera(camera);
  in.width = 96;
  in.height = 64;
  test::renderFromCut(h, in, vp);
  return vp.colorTexture()->readRgba8();
}

TEST(LightBudgetGl, ALightReachingNothingInViewDrawsNothingAndChangesNoPixel) {
  test::GlHarness h;
  const Scene one = lampsScene(false), two = lampsScene(true);
  for (const char* preset : {"cube", "pcss"}) {
    Viewport alone(makeTechnique(preset, {"shadowmap.size=256"}));
    Viewport withFar(makeTechnique(preset, {"shadowmap.size=256"}));
    const std::vector<unsigned char> a = colourOf(h, one, "top", alone);
    const std::vector<unsigned char> b = colourOf(h, two, "top", withFar);
    ASSERT_EQ(a.size(), b.size());
    int worst = 0;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
    EXPECT_LE(worst, 1) << preset << ": the far lamp lights no pixel of this view";
    EXPECT_EQ(withFar.otherLightVisibility(0), nullptr) << preset;
    EXPECT_NE(withFar.status().find("1 reaching nothing in view (not drawn)"), std::string::npos) << withFar.status();
    EXPECT_EQ(withFar.shadowTexels(), alone.shadowTexels()) << preset << ": no maps for the far lamp";
    // The instrument: seen from above both, the far lamp is drawn and lights its ground.
    Viewport seen(makeTechnique(preset, {"shadowmap.size=256"}));
    colourOf(h, two, "both", seen);
    EXPECT_NE(seen.otherLightVisibility(0), nullptr) << preset;
    EXPECT_EQ(seen.status().find("reaching nothing"), std::string::npos) << seen.status();
  }
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

// A lamp of 2 m range beside the first: its visibility test and direct term run only over the
// rectangle its range can reach (Viewport::scissor_). Beyond it the visibility is the test's own
// answer there, unlit (the reference's too), the colour is what shading every pixel with those
// visibilities gives, and the sky outside the rectangle shows that the test did not run there.
TEST(LightBudgetGl, ALampOfShortRangeIsTestedOnlyWhereItReaches) {
  test::GlHarness h;
  const std::string path = test::writeTempFile("short_lamp_" + std::to_string(::getpid()) + ".json", R"({
    "objects":[{"name":"ground","shape":"plane","size":[30,30]},
      {"name":"box","shape":"box","size":[1,1,1],"transform":{"translate":[0,0.5,0]}},
      {"name":"post","shape":"box","size":[0.2,1.2,0.2],"transform":{"translate":[-3.4,0.6,0.3]}}],
    "lights":[{"type":"point","position":[0.5,3,0.5],"range":12},
              {"type":"point","position":[-3,1.5,0],"range":2}],
    "cameras":[{"name":"low","position":[4,3,6],"target":[-1,0,0],"fov_deg":60}]})");
  const test::SceneTruth t = test::sceneTruth(h, path, 160, 90);
  ASSERT_EQ(t.reference.otherLights.size(), 1u);
  Viewport vp(makeTechnique("cube", {"shadowmap.size=256"}));
  test::renderFromCut(h, t.in, vp);
  const Texture2D* tex = vp.otherLightVisibility(0);
  ASSERT_NE(tex, nullptr);
  const std::vector<float> rg = tex->readFloats(2);
  const std::vector<float> v = visibilityChannel(*tex);
  size_t skyNotTested = 0, reached = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    if (!t.reference.valid[i]) skyNotTested += rg[2 * i] == 0.0f && rg[2 * i + 1] == 1.0f;  // the test writes (1, 0)
    reached += t.reference.valid[i] && t.reference.otherLights[0][i] > 0.5f;
  }
  EXPECT_GT(skyNotTested, 100u) << "the lamp's test ran beyond the rectangle its range reaches";
  EXPECT_GT(reached, 100u) << "the lamp lights part of the view";
  const ErrorMetrics e =
      compareVisibility(v.data(), t.reference.otherLights[0].data(), t.reference.valid.data(), v.size());
  EXPECT_LE(e.wrongPixelPct, 3.0);
  // The colour: the scissored sum equals shading every pixel with the same visibilities.
  const std::vector<unsigned char> colour = vp.colorTexture()->readRgba8();
  const std::vector<unsigned char> whole =
      h.renderer.shadeWithVisibility(t.in, visibilityChannel(*vp.visibilityTexture()), {v});
  ASSERT_EQ(colour.size(), whole.size());
  int worst = 0;
  for (size_t i = 0; i < colour.size(); ++i) worst = std::max(worst, std::abs(int(colour[i]) - int(whole[i])));
  EXPECT_LE(worst, 1);
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

// street-lamps at 512² per face hold 3 × 6 × 512² + 512² = 4.98 M texels.
TEST(LightBudgetGl, ATexelBudgetShrinksTheMapsAndKeepsEveryLightNearItsReference) {
  test::GlHarness h;
  const test::SceneTruth t = test::sceneTruth(h, "street-lamps", 160, 90);
  Viewport full(makeTechnique("cube", {"shadowmap.size=512"}));
  Viewport ample(makeTechnique("cube", {"shadowmap.size=512", "lights.texel_budget=5"}));
  Viewport tight(makeTechnique("cube", {"shadowmap.size=512", "lights.texel_budget=1.2"}));
  test::renderFromCut(h, t.in, full);
  const std::vector<unsigned char> fullColour = full.colorTexture()->readRgba8();
  test::renderFromCut(h, t.in, ample);
  EXPECT_EQ(ample.colorTexture()->readRgba8(), fullColour) << "a budget holding every map changes nothing";
  EXPECT_EQ(ample.shadowTexels(), full.shadowTexels());
  test::renderFromCut(h, t.in, tight);
  EXPECT_LE(tight.shadowTexels(), 1200000) << tight.status();
  EXPECT_NE(tight.status().find("M texels"), std::string::npos) << tight.status();
  EXPECT_LE(viewportErrorMetrics(tight, t.reference).wrongPixelPct, 3.0) << "light 1; " << tight.status();
  for (size_t k = 0; k < 3; ++k) {
    const Texture2D* tex = tight.otherLightVisibility(k);
    ASSERT_NE(tex, nullptr) << "light " << k + 2;
    const std::vector<float> v = visibilityChannel(*tex);
    const ErrorMetrics e =
        compareVisibility(v.data(), t.reference.otherLights[k].data(), t.reference.valid.data(), v.size());
    EXPECT_LE(e.wrongPixelPct, 3.0) << "light " << k + 2 << "; " << tight.status();
  }
  const double image =
      viewportImageError(h.renderer, t.in, tight, t.reference.visibility, t.reference.valid, t.reference.otherLights)
          .imageWrongPct;
  EXPECT_LE(image, 3.0) << tight.status();
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

// Views sharing one layer (the cube's faces in an atlas, Liao's packed tetrahedron) cost that
// layer's texels: street-lamps at 1024² hold 4 × 1024² = 4.19 M texels, so a budget of 4.3 M
// keeps every map whole (charged per view, the lamps' maps would halve twice).
TEST(LightBudgetGl, ViewsSharingALayerAreChargedThatLayerOnce) {
  test::GlHarness h;
  const test::SceneTruth t = test::sceneTruth(h, "street-lamps", 160, 90);
  for (const char* preset : {"cube-atlas", "tetrahedron-packed"}) {
    Viewport full(makeTechnique(preset, {"shadowmap.size=1024"}));
    Viewport budgeted(makeTechnique(preset, {"shadowmap.size=1024", "lights.texel_budget=4.3"}));
    test::renderFromCut(h, t.in, full);
    test::renderFromCut(h, t.in, budgeted);
    EXPECT_EQ(full.shadowTexels(), 4 * 1024 * 1024) << preset << ": " << full.status();
    EXPECT_EQ(budgeted.shadowTexels(), full.shadowTexels()) << preset << ": " << budgeted.status();
    EXPECT_EQ(budgeted.colorTexture()->readRgba8(), full.colorTexture()->readRgba8()) << preset;
  }
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

}  // namespace
}  // namespace sl
