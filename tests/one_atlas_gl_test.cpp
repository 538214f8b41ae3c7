// lights.one_atlas (render/one_atlas.cpp): every light's map a region of one shared depth layer.
// Each light must see what its own map showed it (the same visibility, light by light), the
// layer must hold them all at once (a light that cleared the whole layer, or drew outside its
// region, would erase another's), and the lights that cannot share keep their own maps.
#include "tests/gl_test_util.h"
#include "tests/scene_truth_test_util.h"
#include "technique.h"

#include <gtest/gtest.h>

namespace sl {
namespace {

struct LightsSeen {
  std::vector<std::vector<float>> visibility;  // Scene::light's, then each other light's
  std::string status;
  long long texels = 0;
};

LightsSeen render(test::GlHarness& h, const FrameInput& in, const std::string& preset, std::vector<std::string> values,
                  bool oneAtlas) {
  values.push_back(std::string("lights.one_atlas=") + (oneAtlas ? "1" : "0"));
  Viewport vp(makeTechnique(preset, values));
  test::renderFromCut(h, in, vp);
  LightsSeen out;
  out.visibility.push_back(visibilityChannel(*vp.visibilityTexture()));
  for (size_t k = 0; const Texture2D* tex = vp.otherLightVisibility(k); ++k)
    out.visibility.push_back(visibilityChannel(*tex));
  out.status = vp.status();
  out.texels = vp.shadowTexels();
  return out;
}

// Pixels whose visibility differs by more than a tenth.
size_t differing(const std::vector<float>& a, const std::vector<float>& b) {
  size_t n = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) n += std::abs(a[i] - b[i]) > 0.1f;
  return n;
}

// street-lamps: three lamps and a spot. Under cube-atlas every light is one layer (the lamps'
// faces in their atlas, the spot's focused map), so all four share the layer.
void expectEveryLightAsWithItsOwnMap(const std::string& preset, std::vector<std::string> values) {
  test::GlHarness h;
  const test::SceneTruth t = test::sceneTruth(h, "street-lamps", 160, 90);
  values.push_back("shadowmap.size=256");
  values.push_back("lights.texel_budget=0.3");  // 4 x 256² = 0.26 M: every light at 256²
  const LightsSeen own = render(h, t.in, preset, values, false);
  const LightsSeen shared = render(h, t.in, preset, values, true);
  EXPECT_EQ(own.status.find("one atlas"), std::string::npos) << own.status;
  EXPECT_NE(shared.status.find("one atlas 512² for 4 lights (100 % of it)"), std::string::npos) << shared.status;
  EXPECT_EQ(shared.texels, 512 * 512) << "one layer, no map of a light's own: " << shared.status;
  EXPECT_EQ(own.texels, 4 * 256 * 256) << own.status;
  ASSERT_EQ(own.visibility.size(), 4u);
  ASSERT_EQ(shared.visibility.size(), own.visibility.size());
  for (size_t k = 0; k < own.visibility.size(); ++k) {
    // The instrument: each light shadows part of the view, so an erased region would show.
    const std::vector<float>& v = own.visibility[k];
    const size_t shadowed = std::count_if(v.begin(), v.end(), [](float x) { return x < 0.5f; });
    EXPECT_GT(shadowed, 20u) << preset << ": light " << k + 1 << " shadows part of the view";
    EXPECT_LE(differing(own.visibility[k], shared.visibility[k]), v.size() / 200)
        << preset << ": light " << k + 1 << " sees another map in the shared layer";
  }
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

TEST(OneAtlasGl, EveryLightSeesInItsRegionWhatItsOwnMapShowed) { expectEveryLightAsWithItsOwnMap("cube-atlas", {}); }

TEST(OneAtlasGl, FilterTapsStayInTheirLightsRegion) {
  expectEveryLightAsWithItsOwnMap("pcf", {"technique.layout=cube-atlas", "pcf.kernel=5"});
}

// Liao's packed tetrahedron: the four faces' triangles of each light share its region, each
// kept to its triangle by clip distances tested in the region's own square.
TEST(OneAtlasGl, PackedTrianglesKeepToTheirOwnInTheRegion) {
  expectEveryLightAsWithItsOwnMap("tetrahedron-packed", {});
}

// Under `cube` the lamps' maps are six layers each: they keep them, and the spot (one focused
// layer) is alone in the shared layer; the picture is the same.
TEST(OneAtlasGl, LightsOfSeveralLayersKeepTheirOwnMaps) {
  test::GlHarness h;
  const test::SceneTruth t = test::sceneTruth(h, "street-lamps", 160, 90);
  const std::vector<std::string> values = {"shadowmap.size=256", "lights.texel_budget=2"};
  const LightsSeen own = render(h, t.in, "cube", values, false);
  const LightsSeen shared = render(h, t.in, "cube", values, true);
  EXPECT_NE(shared.status.find("one atlas 256² for 1 lights"), std::string::npos) << shared.status;
  EXPECT_EQ(shared.texels, own.texels) << shared.status;
  ASSERT_EQ(shared.visibility.size(), own.visibility.size());
  for (size_t k = 0; k < own.visibility.size(); ++k)
    EXPECT_LE(differing(own.visibility[k], shared.visibility[k]), own.visibility[k].size() / 200) << "light " << k + 1;
}

// The lights' states point at the shared layer between frames: it lives on the heap, not in the
// viewport, so a viewport moved (the explorer's list of them grows) keeps a valid layer, and
// ASan finds a read of the moved-from one.
TEST(OneAtlasGl, AViewportMovedBetweenFramesKeepsItsLayer) {
  test::GlHarness h;
  const test::SceneTruth t = test::sceneTruth(h, "street-lamps", 160, 90);
  auto first = std::make_unique<Viewport>(makeTechnique(
      "cube-atlas", {"shadowmap.size=256", "lights.texel_budget=0.3", "lights.one_atlas=1", "point.keep_faces=1"}));
  test::renderFromCut(h, t.in, *first);
  const std::vector<float> before = visibilityChannel(*first->otherLightVisibility(0));
  Viewport moved(std::move(*first));
  first.reset();
  ASSERT_NE(moved.representation->depthTexture(), nullptr);
  EXPECT_EQ(moved.representation->depthTexture()->width(), 512) << moved.status();
  FrameInput in = t.in;
  h.renderer.render(in, {&moved});  // no cut: the kept faces are read from the layer
  EXPECT_LE(differing(before, visibilityChannel(*moved.otherLightVisibility(0))), before.size() / 200);
}

}  // namespace
}  // namespace sl
