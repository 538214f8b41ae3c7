// The cascaded layout on llvmpipe: finite in every variant, at least as accurate as one focused
// map of the same texel count on the large terrain, and its `cascades` view drawn only when shown.
#include "metrics/metrics.h"
#include "reference/reference.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <algorithm>
#include <set>

namespace sl {
namespace {

using test::Frame;
using test::GlHarness;

Frame renderWith(GlHarness& h, const Scene& scene, const Camera& cam, Viewport& vp, int w, int hgt) {
  FrameInput in;
  in.camera = cam;
  in.width = w;
  in.height = hgt;
  in.cut = true;
  h.renderer.render(in, {&vp});
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  return test::readFrame(h.renderer, vp, w, hgt);
}

using test::wrongPct;

TEST(CascadedGl, EveryVariantIsFiniteInRangeAndErrorFree) {
  GlHarness h;
  for (const std::string id : {"terrain", "dueling-frusta", "spotlight", "columns"}) {
    Scene scene = loadScene(id, defaultAssetsDir());
    h.renderer.setScene(scene);
    for (const std::vector<std::string>& sets : {std::vector<std::string>{"cascades.count=1"},
                                                 {"cascades.count=8", "cascades.scheme=logarithmic"},
                                                 {"cascades.scheme=uniform", "cascades.blend=0.5"},
                                                 {"cascades.warp=lispsm"},
                                                 {"bias.mode=normal-offset"}}) {
      std::vector<std::string> all = sets;
      all.push_back("shadowmap.size=256");
      Viewport vp(makeTechnique("cascaded", all));
      vp.shownViews = vp.availableViews();
      for (const Camera& cam : scene.cameras) {
        Frame f = renderWith(h, scene, cam, vp, 64, 40);
        EXPECT_EQ(f.nonfinite(), 0) << id << " " << cam.name << " " << sets.front();
        for (size_t i = 0; i < f.visibility.size(); i += 2) {
          ASSERT_GE(f.visibility[i], 0.0f) << id << " " << sets.front();
          ASSERT_LE(f.visibility[i], 1.0f) << id << " " << sets.front();
        }
      }
    }
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// Four splits of 512² hold as many texels as one 1024² focused map; on a 2 km terrain seen from
// head height the splits spend them where the pixels are.
TEST(CascadedGl, NoMoreWrongPixelsThanFocusedAtEqualTexelsOnTerrain) {
  GlHarness h;
  Scene scene = loadScene("terrain", defaultAssetsDir());
  h.renderer.setScene(scene);
  Viewport focused(makeTechnique("standard", {"shadowmap.size=1024"}));
  Viewport cascaded(makeTechnique("cascaded", {"shadowmap.size=512", "cascades.count=4"}));
  const Camera& cam = scene.cameras.front();
  const double f = wrongPct(scene, renderWith(h, scene, cam, focused, 320, 180));
  Frame cf = renderWith(h, scene, cam, cascaded, 320, 180);
  const double c = wrongPct(scene, cf);
  std::printf("terrain wrong pixels: focused 1024² %.3f %%, cascaded 4 x 512² %.3f %%\n", f, c);
  EXPECT_EQ(cf.nonfinite(), 0);
  EXPECT_LE(c, f);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// The survey: "z-partitioning works even in cases where warping fails". On `dueling-sunset` the
// camera looks straight into a low sun (sin gamma = 0): LiSPSM falls back to the focused map,
// while face partitioning warps each face from the side and cascades spend texels by depth. At
// equal texels both partitionings must beat the warp (face at 1 M texels, cascades at 4 M).
TEST(CascadedGl, PartitioningBeatsWarpingWhenTheViewLooksIntoTheLight) {
  GlHarness h;
  Scene scene = loadScene("dueling-sunset", defaultAssetsDir());
  h.renderer.setScene(scene);
  const Camera& cam = scene.cameras.front();
  auto wrong = [&](const char* preset, const char* size) {
    Viewport vp(makeTechnique(preset, {size}));
    Frame fr = renderWith(h, scene, cam, vp, 320, 180);
    EXPECT_EQ(fr.nonfinite(), 0) << preset;
    return wrongPct(scene, fr);
  };
  const double warp1 = wrong("lispsm", "shadowmap.size=1024"), face1 = wrong("face-partitioned", "shadowmap.size=512");
  const double warp4 = wrong("lispsm", "shadowmap.size=2048"), z4 = wrong("cascaded", "shadowmap.size=1024");
  std::printf(
      "dueling-sunset wrong pixels: lispsm 1024² %.3f %%, face 4 x 512² %.3f %%; lispsm 2048² %.3f %%, "
      "cascaded 4 x 1024² %.3f %%\n",
      warp1, face1, warp4, z4);
  EXPECT_LT(face1, 0.5 * warp1);
  EXPECT_LT(z4, 0.75 * warp4);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(CascadedGl, CascadesViewShowsEverySplitOnlyWhenShown) {
  GlHarness h;
  Scene scene = loadScene("terrain", defaultAssetsDir());
  h.renderer.setScene(scene);
  Viewport vp(makeTechnique("cascaded", {"shadowmap.size=256"}));
  auto ran = [&](const std::string& name) {
    const auto& passes = h.renderer.stats().passes;
    return std::any_of(passes.begin(), passes.end(), [&](const PassTiming& p) { return p.name == name; });
  };
  renderWith(h, scene, scene.cameras.front(), vp, 160, 90);
  EXPECT_FALSE(ran("view.cascades[0]"));
  vp.shownViews = {"cascades"};
  renderWith(h, scene, scene.cameras.front(), vp, 160, 90);
  EXPECT_TRUE(ran("view.cascades[0]"));
  // Distinct split colours down the image: the ground recedes through the splits. Each pixel is
  // matched to the nearest colour of the view's palette by direction (shading scales it).
  const glm::vec3 palette[4] = {
      {0.90f, 0.30f, 0.25f}, {0.95f, 0.75f, 0.20f}, {0.35f, 0.75f, 0.30f}, {0.25f, 0.55f, 0.90f}};
  const std::vector<unsigned char> img = vp.viewTexture("cascades")->readRgba8();
  std::set<int> hues;
  for (int y = 0; y < 90; y += 2) {
    const unsigned char* px = &img[(static_cast<size_t>(y) * 160 + 80) * 4];
    if (std::max({px[0], px[1], px[2]}) < 40) continue;  // background
    glm::vec3 c = glm::pow(glm::vec3(px[0], px[1], px[2]) / 255.0f, glm::vec3(2.2f));
    int best = 0;
    for (int k = 1; k < 4; ++k)
      if (glm::dot(glm::normalize(c), glm::normalize(palette[k])) >
          glm::dot(glm::normalize(c), glm::normalize(palette[best])))
        best = k;
    hues.insert(best);
  }
  EXPECT_GE(hues.size(), 3u);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace
}  // namespace sl
