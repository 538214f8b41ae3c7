// GPU tests of the foundation on llvmpipe at small sizes: analytic shadows, bias, culling,
// every scene x preset free of NaN and GL errors.
#include "bench/reference_cache.h"
#include "gl_test_util.h"
#include "technique.h"

#include <cmath>
#include <algorithm>
#include <filesystem>
#include <memory>

namespace sl {

using test::Frame;
using test::GlHarness;

namespace {

const char* kBoxScene = R"({
  "objects": [
    {"name": "ground", "shape": "plane", "size": [20, 20], "subdivisions": 4},
    {"name": "box", "shape": "box", "size": [1, 1, 1], "transform": {"translate": [0, 0.5, 0]}}
  ],
  "light": {"type": "directional", "direction": [%LIGHT%]},
  "cameras": [{"name": "c", "position": [-3.5, 4, 2.5], "target": [-0.6, 0, -0.4], "fov_deg": 60, "near": 0.1, "far": 60}]
})";

Scene boxScene(const std::string& light) {
  std::string text = kBoxScene;
  text.replace(text.find("%LIGHT%"), 7, light);
  return loadScene(test::writeTempFile("box_" + std::to_string(std::hash<std::string>()(light)) + ".json", text),
                   defaultAssetsDir());
}

// The exact shadow of the unit box on y = 0: the convex hull of its corners projected along d.
std::vector<glm::vec2> analyticShadow(const glm::vec3& dIn) {
  glm::vec3 d = glm::normalize(dIn);
  std::vector<glm::vec2> pts;
  for (int i = 0; i < 8; ++i) {
    glm::vec3 p(i & 1 ? 0.5f : -0.5f, i & 2 ? 1.0f : 0.0f, i & 4 ? 0.5f : -0.5f);
    glm::vec3 q = p - d * (p.y / d.y);
    pts.emplace_back(q.x, q.z);
  }
  std::sort(pts.begin(), pts.end(), [](auto a, auto b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  auto cross = [](glm::vec2 o, glm::vec2 a, glm::vec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<glm::vec2> hull(16);
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;  // counter-clockwise
}

// Signed distance to the polygon: negative inside.
float signedDistance(const std::vector<glm::vec2>& poly, glm::vec2 p) {
  float dist = 1e30f;
  bool inside = true;
  for (size_t i = 0; i < poly.size(); ++i) {
    glm::vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    glm::vec2 e = b - a;
    float t = glm::clamp(glm::dot(p - a, e) / glm::dot(e, e), 0.0f, 1.0f);
    dist = std::min(dist, glm::length(p - (a + e * t)));
    if (e.x * (p.y - a.y) - e.y * (p.x - a.x) < 0) inside = false;
  }
  return inside ? -dist : dist;
}

struct GroundCount {
  long long ground = 0, insideWrong = 0, outsideWrong = 0, inside = 0, outside = 0;
};

GroundCount compareGround(const Frame& f, const std::vector<glm::vec2>& poly, float band) {
  GroundCount c;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      size_t i = static_cast<size_t>(y) * f.width + x;
      if (f.position[4 * i + 3] < 0.5f || std::abs(f.position[4 * i + 1]) > 1e-3f) continue;
      ++c.ground;
      float sd = signedDistance(poly, glm::vec2(f.position[4 * i], f.position[4 * i + 2]));
      bool lit = f.at(x, y) > 0.5f;
      if (sd < -band) {
        ++c.inside;
        c.insideWrong += lit;
      } else if (sd > band) {
        ++c.outside;
        c.outsideWrong += !lit;
      }
    }
  return c;
}

using test::renderOnce;

}  // namespace

TEST(Render, StandardMatchesTheAnalyticBoxShadowExceptWithinOneTexel) {
  GlHarness h;
  const glm::vec3 d(-0.5f, -1.0f, -0.35f);
  Scene scene = boxScene("-0.5, -1, -0.35");
  Frame f = renderOnce(h, scene, "standard", {"shadowmap.size=2048"}, 320, 180);
  Technique t = makeTechnique("standard", {"shadowmap.size=2048"});
  LayoutInput li{&scene,    0.0, cameraView(scene.cameras[0]), cameraProjection(scene.cameras[0], 320.0f / 180.0f),
                 &t.params, {}};
  LightSpace ls = t.layout->compute(li);
  // One texel of the map, as it lands on the ground (stretched by 1/cos of the light angle).
  float band = ls.primary().texelWorldSize / std::abs(glm::normalize(d).y);
  GroundCount c = compareGround(f, analyticShadow(d), band);
  EXPECT_GT(c.inside, 200);
  EXPECT_GT(c.outside, 5000);
  EXPECT_EQ(c.insideWrong, 0);
  EXPECT_EQ(c.outsideWrong, 0);
  EXPECT_EQ(f.nonfinite(), 0);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(Render, BiasRemovesAcneAtGrazingLightWithoutLosingContactShadow) {
  GlHarness h;
  const glm::vec3 d(-1.0f, -0.27f, -0.25f);  // about 15 degrees above the ground
  Scene scene = boxScene("-1, -0.27, -0.25");
  auto poly = analyticShadow(d);
  std::map<std::string, GroundCount> counts;
  for (const std::string mode : {"none", "constant", "slope", "normal-offset"}) {
    Frame f = renderOnce(h, scene, "standard", {"shadowmap.size=1024", "bias.mode=" + mode}, 320, 180);
    Technique t = makeTechnique("standard", {"shadowmap.size=1024"});
    LayoutInput li{&scene,    0.0, cameraView(scene.cameras[0]), cameraProjection(scene.cameras[0], 320.0f / 180.0f),
                   &t.params, {}};
    float band = 2.0f * t.layout->compute(li).primary().texelWorldSize / std::abs(glm::normalize(d).y);
    counts[mode] = compareGround(f, poly, band);
    EXPECT_EQ(f.nonfinite(), 0);
  }
  auto acne = [&](const std::string& m) { return double(counts[m].outsideWrong) / double(counts[m].outside); };
  auto leak = [&](const std::string& m) { return double(counts[m].insideWrong) / double(counts[m].inside); };
  std::printf("acne: none %.4f constant %.4f slope %.4f normal-offset %.4f\n", acne("none"), acne("constant"),
              acne("slope"), acne("normal-offset"));
  std::printf("lost contact shadow: slope %.4f normal-offset %.4f\n", leak("slope"), leak("normal-offset"));
  EXPECT_GT(acne("none"), 0.2);  // the grazing plane shadows itself all over
  EXPECT_LT(acne("slope"), acne("none") * 0.05);
  EXPECT_LT(acne("slope"), 0.005);
  EXPECT_LT(acne("normal-offset"), 0.005);
  EXPECT_LT(leak("slope"), 0.01);  // the shadow under the box stays
  EXPECT_LT(leak("normal-offset"), 0.01);
  EXPECT_GT(counts["slope"].inside, 200);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// On a GPU the pass times come from timer queries: the bench waits for its frame's own, the
// explorer takes the newest that have arrived (no stall). Forced here on llvmpipe, whose
// timestamps do not measure the work: the names and their order are what is checked.
TEST(Render, PassTimesFromQueriesNameTheFramesPassesWaitedForOrNot) {
  GlHarness h;
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  h.renderer.forceTimerQueries = true;
  Viewport vp(makeTechnique("standard", {"shadowmap.size=256"}));
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 96;
  in.height = 64;
  const std::vector<std::string> expected = {"gbuffer", "shadowmap[0]", "shade[0]"};
  auto passNames = [&] {
    std::vector<std::string> n;
    for (const auto& p : h.renderer.stats().passes) {
      n.push_back(p.name);
      EXPECT_TRUE(std::isfinite(p.ms) && p.ms >= 0.0) << p.name << ": " << p.ms;
    }
    return n;
  };
  h.renderer.render(in, {&vp});
  EXPECT_EQ(h.renderer.stats().timer, "gpu-query");
  EXPECT_EQ(passNames(), expected);
  h.renderer.waitForPassTimes = false;
  for (int frame = 0; frame < 4; ++frame) {
    h.renderer.render(in, {&vp});
    EXPECT_EQ(passNames(), expected) << "frame " << frame << ": arrived or not, a whole frame's passes";
  }
  glFinish();
  h.renderer.render(in, {&vp});
  EXPECT_EQ(passNames(), expected);
  EXPECT_TRUE(std::isfinite(h.renderer.stats().frameMs));
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(Render, OnlyShownViewsCostAPass) {
  GlHarness h;
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  Viewport vp(makeTechnique("standard", {"shadowmap.size=256"}));
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 96;
  in.height = 64;
  auto passNames = [&] {
    std::vector<std::string> n;
    for (const auto& p : h.renderer.stats().passes) n.push_back(p.name);
    return n;
  };
  h.renderer.render(in, {&vp});
  // No accumulation: visibility is computed inside the shade pass.
  EXPECT_EQ(passNames(), (std::vector<std::string>{"gbuffer", "shadowmap[0]", "shade[0]"}));
  vp.shownViews = {"texels", "lightspace"};
  h.renderer.render(in, {&vp});
  auto names = passNames();
  EXPECT_EQ(names.size(), 5u);
  EXPECT_NE(std::find(names.begin(), names.end(), "view.texels[0]"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "view.lightspace[0]"), names.end());
  EXPECT_EQ(std::find(names.begin(), names.end(), "view.aliasing[0]"), names.end());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// The blur's scratch target is the frame graph's: two viewports of one map size borrow the same
// texture in turn, and later frames reuse it (one texture in the pool, not one per viewport).
TEST(Render, BlurScratchIsOneGraphTextureSharedByViewports) {
  GlHarness h;
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  Viewport a(makeTechnique("vsm", {"shadowmap.size=128", "filter.width=5"}));
  Viewport b(makeTechnique("vsm", {"shadowmap.size=128", "filter.width=3"}));
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 64;
  in.height = 48;
  h.renderer.render(in, {&a, &b});
  EXPECT_EQ(h.renderer.transientTextures().textures(), 1);
  EXPECT_EQ(h.renderer.transientTextures().texels(), 128LL * 128);
  h.renderer.render(in, {&a, &b});
  EXPECT_EQ(h.renderer.transientTextures().textures(), 1);
  // Without a blur nothing is borrowed, and after a while the pool lets the target go.
  Viewport c(makeTechnique("standard", {"shadowmap.size=128"}));
  for (int k = 0; k <= TransientTextures::kKeepFrames; ++k) h.renderer.render(in, {&c});
  EXPECT_EQ(h.renderer.transientTextures().textures(), 0);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// One test per (builtin scene, preset), every camera of the scene, every view of the preset
// shown. ctest runs the tests of one scene in one process (CMakeLists.txt adds them as
// EveryPreset/<scene>), so they share a GL context, the compiled programs and the loaded scene:
// split into one process per test, the sweep loaded Sponza 123 times.
struct ScenePreset {
  std::string scene, preset;
};
void PrintTo(const ScenePreset& c, std::ostream* os) { *os << c.scene << " " << c.preset; }

std::vector<ScenePreset> everyScenePreset() {
  std::vector<ScenePreset> cases;
  for (const std::string& scene : builtinSceneIds(defaultAssetsDir()))
    for (const auto& preset : allPresets()) cases.push_back({scene, preset.id});
  return cases;
}

// The reference of a scene's first camera at the accuracy test's size and standard's wrong
// pixels against it, made once per process and scene.
struct SceneTruth {
  std::string scene;
  FrameInput in;
  ReferenceImage reference;
  double standardWrongPct = 0, standardImageWrongPct = 0;
};

class EveryPreset : public ::testing::TestWithParam<ScenePreset> {
 protected:
  static void SetUpTestSuite() { harness_ = std::make_unique<GlHarness>(); }
  static void TearDownTestSuite() {
    harness_->requireAllUniformsSet = false;  // checked by each test
    harness_.reset();
    sceneId_.clear();
  }
  // The scene of this test, loaded once per process; nullptr (and the test skipped) where it is
  // built on shared/scenes-real and that folder is absent.
  const Scene* scene(const std::string& id) {
    if (sceneId_ != id) {
      try {
        scene_ = loadScene(id, defaultAssetsDir());
      } catch (const SceneError& e) {
        if (std::string(e.what()).find("scenes-real") != std::string::npos) return nullptr;
        throw;
      }
      sceneId_ = id;
      harness_->renderer.setScene(scene_);
    }
    return &scene_;
  }
  static const SceneTruth& truth(const std::string& id);
  static inline std::unique_ptr<GlHarness> harness_;
  static inline Scene scene_;
  static inline std::string sceneId_;
  static inline SceneTruth truth_;
};

// In a scene of several lights the sweep measures the first (Scene::light); each light against
// its own reference is tests/many_lights_gl_test.cpp's, so the others are left unshadowed here.
std::vector<std::string> firstLightOnly(const Scene& scene) {
  if (scene.otherLights.empty()) return {};
  return {"lights.shadowed=1"};
}

constexpr int kAccuracyW = 320, kAccuracyH = 180;

const SceneTruth& EveryPreset::truth(const std::string& id) {
  if (truth_.scene == id) return truth_;
  truth_ = SceneTruth{id, {}, {}, 0, 0};
  truth_.in.camera = scene_.cameras.front();
  truth_.in.width = kAccuracyW;
  truth_.in.height = kAccuracyH;
  ReferenceSettings rs;
  rs.samples = 16;
  ReferenceCache cache(scene_, rs);
  truth_.reference = cache.forFrame(harness_->renderer, truth_.in);
  Viewport standard(makeTechnique("standard", firstLightOnly(scene_)));
  test::renderFromCut(*harness_, truth_.in, standard);
  truth_.standardWrongPct = viewportErrorMetrics(standard, truth_.reference).wrongPixelPct;
  truth_.standardImageWrongPct =
      viewportImageError(harness_->renderer, truth_.in, standard, truth_.reference.visibility, truth_.reference.valid,
                         truth_.reference.otherLights)
          .imageWrongPct;
  return truth_;
}

// Measured exceptions to the bar below, each with its cause (README.md, "Every preset on every
// scene"). Where the light grazes the receivers (dueling-sunset's sunset, 6° up; terrain's
// slopes turned from the light) filtered presets' kernels stretch with the texels over surfaces
// the shading leaves dark: their visibility is off against the hard reference but the shaded
// image is not, so there they are held to the image. Forward splats leave the method's holes
// where a light texel spans more pixels than a splat reaches or its centre falls outside the
// view (grazing's 0.06° light, terrain's near ground): those are held to being finite.
bool heldToTheImage(const std::string& scene, const std::string& preset) {
  static const std::vector<std::string> filtered = {"pcf",
                                                    "poisson",
                                                    "pixel-correct-pcf",
                                                    "vsm",
                                                    "esm",
                                                    "evsm2",
                                                    "evsm4",
                                                    "gaussian",
                                                    "ewgf",
                                                    "msm",
                                                    "lvsm",
                                                    "msm16",
                                                    "convolution",
                                                    "vssm",
                                                    "pcss",
                                                    "optimized-pcf",
                                                    "pixel-correct-optimized-pcf",
                                                    "cube-pcf",
                                                    "tetrahedron-pcf",
                                                    "tetrahedron-packed-pcf",
                                                    "dual-paraboloid-pcf"};
  if (scene == "terrain") return preset == "pcss";
  return scene == "dueling-sunset" && std::find(filtered.begin(), filtered.end(), preset) != filtered.end();
}
// A point light amid the scene (street's lamp) reaches single-frustum layouts as a spot aimed at
// the visible receivers, its cone at most 160 degrees (layoutLight): the filtered presets'
// kernels then span stretched texels near the cone's rim and leak (5-10 % wrong at 320x180,
// README), which is what the point family's cube layout is for. Presets on such a layout are
// held to a looser bar, still one a regression fails.
constexpr double kPointAsSpotBar = 12.0;
// sponza-lamps' first lamp hangs in an arcade with Sponza all around it: the cone leaves more of
// the view outside it, lit (the virtual family fits it to the whole scene: 15.7-16.2 % wrong,
// standard 4.1 %, cube 0.17 %; README).
constexpr double kPointAsSpotInSponzaBar = 18.0;
bool pointLightThroughOneFrustum(const Scene& scene, const std::string& preset) {
  const Preset* p = findPreset(preset);
  static const std::vector<std::string> pointLayouts = {"cube", "tetrahedron", "tetrahedron-packed", "dual-paraboloid"};
  return scene.light.type == Light::Type::Point && p &&
         std::find(pointLayouts.begin(), pointLayouts.end(), p->layout) == pointLayouts.end();
}
// Issue #23's bar: with its defaults, every preset is finite and at most max(5 %, 3x standard's)
// wrong pixels against the ray-traced reference, on every builtin scene (first camera,
// 320x180, two frames from a cut), except the measured cases above.
TEST_P(EveryPreset, WithinThreeTimesStandardsWrongPixels) {
  const auto& [id, preset] = GetParam();
  const Scene* s = scene(id);
  if (!s) GTEST_SKIP() << id << " needs shared/scenes-real";
  const SceneTruth& t = truth(id);
  Viewport vp(makeTechnique(preset, firstLightOnly(*s)));
  test::renderFromCut(*harness_, t.in, vp);
  const ErrorMetrics m = viewportErrorMetrics(vp, t.reference);
  EXPECT_EQ(m.nonfinite, 0) << id << " " << preset;
  double bar = std::max(5.0, 3.0 * t.standardWrongPct);
  if (pointLightThroughOneFrustum(*s, preset))
    bar = std::max(id == "sponza-lamps" ? kPointAsSpotInSponzaBar : kPointAsSpotBar, bar);
  // Forward mapping under a sun 0.06 degrees up: a ground texel spans more pixels than the
  // largest splat (255 pixels a side), the method's limit (techniques/reconstruction/README.md).
  if (preset == "forward" && id == "grazing") return;
  if (heldToTheImage(id, preset)) {
    const ImageErrorMetrics image = viewportImageError(harness_->renderer, t.in, vp, t.reference.visibility,
                                                       t.reference.valid, t.reference.otherLights);
    EXPECT_LE(image.imageWrongPct, std::max(1.0, 3.0 * t.standardImageWrongPct))
        << id << " " << preset << ": visibility " << m.wrongPixelPct << " % wrong, and the shaded image differs "
        << "too (standard's image " << t.standardImageWrongPct << " %)";
    return;
  }
  EXPECT_LE(m.wrongPixelPct, bar) << id << " " << preset << ": standard " << t.standardWrongPct << " %";
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryPreset, ::testing::ValuesIn(everyScenePreset()), [](const auto& info) {
  std::string name = info.param.scene + "__" + info.param.preset;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
});

}  // namespace sl
