// The pre-filtered soft representations (vssm, convolution-soft) on llvmpipe: finite and in [0,1]
// from a point light to a huge disk, over cascades and under the pixel-correct history, a status naming the light they
// model, no pass beyond the map's own table, and on `contact` closer to the area-light reference than fixed-width PCF.
#include "soft/soft_gl_test_util.h"
#include "technique.h"

#include <algorithm>

namespace sl {
namespace {

using test::Frame;
using test::GlHarness;

Frame renderMomentSoft(GlHarness& h, const Scene& scene, Viewport& vp, int w, int hgt) {
  return test::renderSoft(h, scene, vp, w, hgt);
}

const char* kSoftMomentPresets[] = {"vssm", "convolution-soft"};

// One test per (light case, preset): a failure names its case, and none runs long under the
// sanitizers.
struct SoftMomentCase {
  test::LightCase light;
  const char* preset;
};
void PrintTo(const SoftMomentCase& c, std::ostream* os) {
  *os << c.light.scene << " radius " << c.light.radius << " " << c.preset;
}

std::vector<SoftMomentCase> softMomentCases() {
  std::vector<SoftMomentCase> cases;
  for (const test::LightCase& c : test::softLightCases())
    for (const char* preset : kSoftMomentPresets) cases.push_back({c, preset});
  return cases;
}

class MomentSoftLights : public ::testing::TestWithParam<SoftMomentCase> {};

TEST_P(MomentSoftLights, FiniteAndInRangeFromPointToHugeLights) {
  const SoftMomentCase& c = GetParam();
  GlHarness h;
  const Scene scene = test::loadLightCase(c.light);
  h.renderer.setScene(scene);
  for (const auto& [layout, accumulation] : std::vector<std::pair<std::string, std::string>>{
           {"focused", "none"}, {"cascaded", "none"}, {"uniform", "pixel-correct"}}) {
    // The preset's representation and overrides over each layout.
    const Preset* p = findPreset(c.preset);
    std::vector<std::string> sets = p->overrides;
    sets.push_back("shadowmap.size=128");
    Viewport vp(test::compose(layout, p->representation, accumulation, sets));
    vp.shownViews = vp.availableViews();
    test::expectFiniteShadowAndLight(renderMomentSoft(h, scene, vp, 64, 40),
                                     std::string(c.light.scene) + " radius " + std::to_string(c.light.radius) + " " +
                                         c.preset + " " + layout + " " + accumulation);
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

INSTANTIATE_TEST_SUITE_P(Cases, MomentSoftLights, ::testing::ValuesIn(softMomentCases()), [](const auto& info) {
  const SoftMomentCase& c = info.param;
  std::string name = std::string(c.light.scene) + "__" + c.preset + "__" + std::to_string(info.index);
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
});

// The status's first part, before the share of the map the filter pass covered.
std::string statusOfTheLight(const Viewport& vp) {
  const std::string s = vp.representation->status();
  return s.substr(0, s.find("; "));
}

std::vector<std::string> passNames(const GlHarness& h) {
  std::vector<std::string> passes;
  for (const auto& p : h.renderer.stats().passes) passes.push_back(p.name);
  return passes;
}

TEST(MomentSoftGl, StatusNamesTheLightAndTheOneExtraPassIsATableOnlyUnderAnAreaLight) {
  GlHarness h;
  for (const char* preset : kSoftMomentPresets) {
    const Scene soft = loadScene("soft", defaultAssetsDir());
    h.renderer.setScene(soft);
    Viewport vp(makeTechnique(preset, {"shadowmap.size=128"}));
    renderMomentSoft(h, soft, vp, 32, 20);
    // The light, then the share of the map the table covers (the texels visible receivers read).
    EXPECT_EQ(statusOfTheLight(vp), std::string(preset) + ": light radius 0.03 x 1");
    EXPECT_NE(vp.representation->status().find("summed-area table over "), std::string::npos);
    EXPECT_EQ(passNames(h), (std::vector<std::string>{"gbuffer", "shadowmap[0]", "prefilter.sat[0]", "shade[0]"}));
    const Scene basic = loadScene("basic", defaultAssetsDir());
    h.renderer.setScene(basic);
    renderMomentSoft(h, basic, vp, 32, 20);
    EXPECT_EQ(statusOfTheLight(vp),
              std::string(preset) + ": point light (radius 0): no blocker estimate, minimum-kernel box");
    // Its one box, two texels wide, is read from the moments themselves: no table is made.
    EXPECT_EQ(passNames(h), (std::vector<std::string>{"gbuffer", "shadowmap[0]", "prefilter.moments[0]", "shade[0]"}));
    EXPECT_NE(vp.representation->status().find("moments over "), std::string::npos);
  }
}

// Where the `penumbra` view shows a blocker estimate: not black (lit) and not grey (not searched).
std::vector<bool> blockersFound(const Viewport& vp) {
  const std::vector<unsigned char> px = vp.viewTexture("penumbra")->readRgba8();
  std::vector<bool> found;
  for (size_t i = 0; i < px.size(); i += 4) {
    const int r = px[i], g = px[i + 1], b = px[i + 2];
    const bool black = r < 8 && g < 8 && b < 8,
               grey = std::abs(r - 64) < 4 && std::abs(g - 64) < 4 && std::abs(b - 64) < 4;
    found.push_back(!black && !grey);
  }
  return found;
}

// The `penumbra` view shows where each soft technique found blockers (coloured) and where not
// (black: lit; grey: not searched). On `contact` the three estimates (pcss's taps, vssm's
// moments, CSM-Z's basis) find blockers over about the same pixels: the shadow of the pole.
TEST(MomentSoftGl, PenumbraViewsFindTheBlockersPcssFinds) {
  GlHarness h;
  const Scene scene = loadScene("contact", defaultAssetsDir());
  h.renderer.setScene(scene);
  auto found = [&](const char* preset) {
    Viewport vp(makeTechnique(preset, {"shadowmap.size=512"}));
    vp.shownViews = {"penumbra", "blocker-depth"};
    renderMomentSoft(h, scene, vp, 160, 90);
    return blockersFound(vp);
  };
  const std::vector<bool> pcss = found("pcss");
  const int pcssCount = static_cast<int>(std::count(pcss.begin(), pcss.end(), true));
  ASSERT_GT(pcssCount, 100);
  for (const char* preset : kSoftMomentPresets) {
    const std::vector<bool> other = found(preset);
    ASSERT_EQ(other.size(), pcss.size());
    int both = 0, either = 0;
    for (size_t i = 0; i < pcss.size(); ++i) {
      both += pcss[i] && other[i];
      either += pcss[i] || other[i];
    }
    // Intersection over union of the two blocker masks.
    EXPECT_GT(double(both) / either, 0.6)
        << preset << ": " << both << " of " << either << " (pcss " << pcssCount << ")";
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// VSSM's kernel subdivision (Yang et al. 2010, vssm.subdivide, off by default): where the whole
// search box gives no blocker (the receiver not beyond its mean depth), its sub-boxes are
// estimated alone, each against the receiver's plane at its centre. Every pixel that had an
// estimate keeps it, the error does not grow, and the sub-boxes invent no blockers where pcss's
// taps find none: compared with the pixel's own depth, the sub-boxes beyond it on `contact`'s
// ground (sloped in the light's view) read as blockers over about half of the picture.
TEST(MomentSoftGl, VssmKernelSubdivisionKeepsEstimatesAndInventsNoBlockers) {
  GlHarness h;
  const Scene scene = loadScene("contact", defaultAssetsDir());
  h.renderer.setScene(scene);
  // rmse: where to put the error against the reference (null: not traced).
  auto run = [&](const std::string& preset, const char* subdivide, double* rmse) {
    Viewport vp(makeTechnique(preset, subdivide ? std::vector<std::string>{std::string("vssm.subdivide=") + subdivide}
                                                : std::vector<std::string>{}));
    vp.shownViews = {"penumbra"};
    const Frame f = renderMomentSoft(h, scene, vp, 192, 108);
    if (rmse) *rmse = test::visibilityError(scene, f).rmse;
    return blockersFound(vp);
  };
  double wholeRmse = 0, subRmse = 0;
  const std::vector<bool> whole = run("vssm", "0", &wholeRmse), sub = run("vssm", "2", &subRmse),
                          pcss = run("pcss", nullptr, nullptr);
  ASSERT_EQ(whole.size(), sub.size());
  ASSERT_EQ(pcss.size(), sub.size());
  int kept = 0, wholeCount = 0, added = 0, invented = 0;
  for (size_t i = 0; i < whole.size(); ++i) {
    wholeCount += whole[i];
    kept += whole[i] && sub[i];
    added += !whole[i] && sub[i];
    invented += !whole[i] && sub[i] && !pcss[i];
  }
  std::printf(
      "contact 192x108: blockers found whole %d, subdivided keeps %d, adds %d (%d where pcss finds none); "
      "rmse %.4f -> %.4f\n",
      wholeCount, kept, added, invented, wholeRmse, subRmse);
  ASSERT_GT(wholeCount, 100);
  EXPECT_GE(kept, wholeCount * 99 / 100);  // a few may differ where an estimate sits at the threshold
  EXPECT_GT(added, 0) << "no pixel gained a blocker estimate";
  EXPECT_LE(invented, int(whole.size()) / 200) << "sub-boxes read the receiver's own ground as blockers";
  EXPECT_LE(subRmse, wholeRmse + 0.0005);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// The aim the soft family shares: at most half of fixed-width PCF's rmse against the area-light
// reference on the scene whose penumbra grows from a contact.
TEST(MomentSoftGl, VssmOnContactHalvesPcfError) {
  GlHarness h;
  const Scene scene = loadScene("contact", defaultAssetsDir());
  h.renderer.setScene(scene);
  auto rmse = [&](const char* preset) { return test::softRmse(h, scene, preset, 192, 108); };
  const double pcf = rmse("pcf"), vssm = rmse("vssm"), csmz = rmse("convolution-soft");
  EXPECT_GT(pcf, 0.02);
  EXPECT_LT(vssm, 0.5 * pcf) << "vssm " << vssm << " pcf " << pcf;
  // CSM-Z at 4 terms is not that close (README): it must at least not be worse than PCF.
  EXPECT_LT(csmz, pcf) << "convolution-soft " << csmz << " pcf " << pcf;
}

}  // namespace
}  // namespace sl
