// PCSS on llvmpipe: the blocker search is a pass of its own only under an area light, the result
// is finite and in [0,1] for lights from a point to a huge disk and on every layout, a search that
// finds nothing leaves the receiver lit, and on `contact` it is at least twice as close to the
// area-light reference as fixed-width PCF.
#include "metrics/metrics.h"
#include "reference/reference.h"
#include "scene/scene_effects.h"
#include "soft/soft_gl_test_util.h"
#include "technique.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace sl {
namespace {

using test::Frame;
using test::GlHarness;

std::vector<std::string> passNames(const Renderer& r) {
  std::vector<std::string> n;
  for (const auto& p : r.stats().passes) n.push_back(p.name);
  return n;
}

Frame render(GlHarness& h, const Scene& scene, Viewport& vp, int w, int hgt) {
  return test::renderSoft(h, scene, vp, w, hgt);
}

TEST(PcssGl, BlockerSearchPassOnlyUnderAnAreaLight) {
  GlHarness h;
  const Scene soft = loadScene("soft", defaultAssetsDir());
  const Scene basic = loadScene("basic", defaultAssetsDir());
  for (const char* preset : {"pcss", "pcss-cascaded"}) {
    h.renderer.setScene(soft);
    Viewport vp(makeTechnique(preset, {"shadowmap.size=256"}));
    render(h, soft, vp, 64, 40);
    EXPECT_EQ(passNames(h.renderer),
              (std::vector<std::string>{"gbuffer", "shadowmap[0]", "blocker-search[0]", "shade[0]"}))
        << preset;
    EXPECT_NE(vp.representation->status().find("light radius 0.03"), std::string::npos) << vp.representation->status();

    h.renderer.setScene(basic);
    Viewport hard(makeTechnique(preset, {"shadowmap.size=256"}));
    hard.shownViews = hard.availableViews();  // its own views must not bring the search back
    render(h, basic, hard, 64, 40);
    for (const auto& n : passNames(h.renderer)) EXPECT_EQ(n.rfind("blocker", 0), std::string::npos) << n;
    EXPECT_NE(hard.representation->status().find("no blocker search"), std::string::npos);
  }
  // The views read the search: shown, they run after it.
  h.renderer.setScene(soft);
  Viewport vp(makeTechnique("pcss", {"shadowmap.size=256"}));
  vp.shownViews = {"blocker-depth", "penumbra"};
  render(h, soft, vp, 64, 40);
  const auto names = passNames(h.renderer);
  const auto search = std::find(names.begin(), names.end(), "blocker-search[0]");
  ASSERT_NE(search, names.end());
  EXPECT_LT(search, std::find(names.begin(), names.end(), "view.penumbra[0]"));
  EXPECT_NE(std::find(names.begin(), names.end(), "view.blocker-depth[0]"), names.end());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(PcssGl, HardTechniquesSayTheyIgnoreTheRadius) {
  GlHarness h;
  const Scene soft = loadScene("soft", defaultAssetsDir());
  h.renderer.setScene(soft);
  const Scene basic = loadScene("basic", defaultAssetsDir());
  // Depth tests and pre-filtered maps alike: a fixed filter is no penumbra.
  for (const std::string preset : {"pcf", "vsm"}) {
    h.renderer.setScene(soft);
    Viewport vp(makeTechnique(preset, {"shadowmap.size=256"}));
    render(h, soft, vp, 32, 20);
    // (vsm's status goes on with the share of the map its blur filtered.)
    EXPECT_EQ(vp.representation->status().rfind("hard: ignores light radius 0.03", 0), 0u)
        << preset << ": " << vp.representation->status();
    h.renderer.setScene(basic);
    render(h, basic, vp, 32, 20);
    EXPECT_EQ(vp.representation->status().find("radius"), std::string::npos)
        << preset << ": " << vp.representation->status();
  }
}

TEST(PcssGl, FiniteAndInRangeFromPointToHugeLights) {
  GlHarness h;
  for (const test::LightCase& c : test::softLightCases()) {
    const Scene scene = test::loadLightCase(c);
    h.renderer.setScene(scene);
    for (const char* preset : {"pcss", "pcss-cascaded"}) {
      for (const char* rotate : {"pcss.rotate=on", "pcss.rotate=off"}) {
        Viewport vp(makeTechnique(preset, {"shadowmap.size=256", rotate}));
        vp.shownViews = vp.availableViews();
        test::expectFiniteShadowAndLight(
            render(h, scene, vp, 64, 40),
            std::string(c.scene) + " " + std::to_string(c.radius) + " " + preset + " " + rotate);
      }
    }
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(PcssGl, SearchThatFindsNothingIsLit) {
  namespace fs = std::filesystem;
  const fs::path p = fs::temp_directory_path() / ("shadowlab_pcss_plane_" + std::to_string(::getpid()) + ".json");
  std::ofstream(p) << R"({"objects":[{"shape":"plane","size":[10,10]}],
                         "light":{"direction":[0.3,-1,0.2],"radius":0.08},
                         "cameras":[{"position":[0,6,6],"target":[0,0,0]}]})";
  const Scene scene = loadScene(p.string(), defaultAssetsDir());
  fs::remove(p);
  GlHarness h;
  h.renderer.setScene(scene);
  Viewport vp(makeTechnique("pcss", {"shadowmap.size=256"}));
  const Frame f = render(h, scene, vp, 64, 40);
  int covered = 0;
  for (int i = 0; i < f.width * f.height; ++i) {
    if (f.position[4 * i + 3] < 0.5f) continue;
    ++covered;
    EXPECT_EQ(f.visibility[2 * i], 1.0f) << "pixel " << i;
  }
  EXPECT_GT(covered, 500);
}

// The aim of the soft family on its own scene: pcss at most half of pcf's rmse against the
// area-light reference, on one map and on cascades.
TEST(PcssGl, ContactPenumbraHalvesPcfError) {
  GlHarness h;
  const Scene scene = loadScene("contact", defaultAssetsDir());
  h.renderer.setScene(scene);
  auto rmse = [&](const char* preset) { return test::softRmse(h, scene, preset, 192, 108); };
  const double pcf = rmse("pcf"), pcss = rmse("pcss"), cascaded = rmse("pcss-cascaded");
  EXPECT_GT(pcf, 0.02);  // the scene does call for soft shadows
  EXPECT_LT(pcss, 0.5 * pcf) << "pcss " << pcss << " pcf " << pcf;
  EXPECT_LT(cascaded, 0.5 * pcf) << "pcss-cascaded " << cascaded << " pcf " << pcf;
}

}  // namespace
}  // namespace sl
