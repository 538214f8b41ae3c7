// Silhouette maps and forward shadow mapping on llvmpipe, small frames: the silhouette map beats
// the plain depth map on straight-edged casters at equal resolution; both stay finite and in
// [0, 1] on the hard cases and on the real glTF scenes; forward mapping's holes shrink as its
// splats grow, and its gather lights what its scatter lights.
#include "layouts/hard_cases.h"
#include "metrics/metrics.h"
#include "reconstruction/silhouette_state.h"
#include "reference/reference.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <filesystem>

namespace sl {
namespace {

using test::wrongPct;

void expectSane(const test::Frame& f, const std::string& what) {
  EXPECT_EQ(f.nonfinite(), 0) << what;
  for (size_t i = 0; i < f.visibility.size(); i += 2)
    if (!(f.visibility[i] >= 0.0f && f.visibility[i] <= 1.0f)) {
      ADD_FAILURE() << what << ": visibility " << f.visibility[i] << " outside [0, 1]";
      break;
    }
}

// Two boxes, one turned 30 degrees, on a plane under an oblique sun: only straight edges.
Scene boxesScene() {
  const std::string json = R"({
    "name": "boxes",
    "objects": [
      {"name": "ground", "shape": "plane", "size": [12, 12], "color": [0.8, 0.8, 0.8]},
      {"name": "a", "shape": "box", "size": [1, 1.5, 1], "transform": {"translate": [0, 0.75, 0], "rotate_deg": [0, 30, 0]}},
      {"name": "b", "shape": "box", "size": [2, 0.6, 0.4], "transform": {"translate": [-1.5, 0.3, 1.2], "rotate_deg": [0, -12, 0]}}
    ],
    "light": {"type": "directional", "direction": [0.6, -0.7, 0.35]},
    "cameras": [{"name": "default", "position": [3, 3, 5], "target": [-0.5, 0, 0], "fov_deg": 55}]
  })";
  return loadScene(test::writeTempFile("boxes_scene.json", json), defaultAssetsDir());
}

TEST(Silhouette, BeatsStandardOnStraightEdgesAtEqualResolution) {
  test::GlHarness h;
  const Scene scene = boxesScene();
  for (int size : {128, 256}) {
    const std::vector<std::string> sets = {"shadowmap.size=" + std::to_string(size)};
    const test::Frame standard = test::renderOnce(h, scene, "standard", sets, 240, 135);
    const test::Frame silhouette = test::renderOnce(h, scene, "silhouette", sets, 240, 135);
    expectSane(silhouette, "silhouette");
    const double ws = wrongPct(scene, standard), wr = wrongPct(scene, silhouette);
    std::printf("boxes %d^2: standard %.3f %% wrong, silhouette %.3f %%\n", size, ws, wr);
    EXPECT_GT(ws, 0.1) << "the map is coarse enough that standard has blocky edges";
    EXPECT_LT(wr, 0.5 * ws) << size;
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(Silhouette, StoresPointsInsideTheirTexelsOnTheLightsSilhouettes) {
  test::GlHarness h;
  const Scene scene = boxesScene();
  h.renderer.setScene(scene);
  Viewport vp(makeTechnique("silhouette", {"shadowmap.size=128"}));
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 160;
  in.height = 90;
  h.renderer.render(in, {&vp});
  auto* state = dynamic_cast<SilhouetteMapState*>(vp.representation.get());
  ASSERT_NE(state, nullptr);
  // Two boxes: four silhouette edges each at least, plus the ground's rim.
  EXPECT_GE(state->segmentCount(), 12u);
  const std::vector<float> points = state->silhouetteMap().readFloats(2);
  long long stored = 0;
  for (size_t i = 0; i < points.size(); i += 2) {
    if (points[i] < 0.0f) {
      EXPECT_EQ(points[i + 1], -1.0f);
      continue;
    }
    ++stored;
    ASSERT_GE(points[i], 0.0f);
    ASSERT_LE(points[i], 1.0f);
    ASSERT_GE(points[i + 1], 0.0f);
    ASSERT_LE(points[i + 1], 1.0f);
  }
  // Outlines, not areas: some texels, far fewer than the map has.
  EXPECT_GT(stored, 100);
  EXPECT_LT(stored, static_cast<long long>(points.size() / 2) / 10);
}

TEST(Silhouette, OffIsTheStandardMap) {
  test::GlHarness h;
  const Scene scene = boxesScene();
  const test::Frame standard = test::renderOnce(h, scene, "standard", {"shadowmap.size=128"}, 160, 90);
  const test::Frame off =
      test::renderOnce(h, scene, "silhouette", {"shadowmap.size=128", "silhouette.reconstruct=off"}, 160, 90);
  long long differ = 0;
  for (size_t i = 0; i < off.visibility.size(); i += 2) differ += off.visibility[i] != standard.visibility[i];
  EXPECT_EQ(differ, 0) << "without the points the corner tests pick the nearest sample, as standard does";
}

TEST(Forward, HolesShrinkAsSplatsGrow) {
  test::GlHarness h;
  const Scene scene = loadScene("basic", defaultAssetsDir());
  const std::vector<std::string> base = {"shadowmap.size=256"};
  auto with = [&](const std::string& splat) {  // Zhang's fixed splats (forward.grow off)
    std::vector<std::string> s = base;
    s.push_back("forward.splat=" + splat);
    s.push_back("forward.grow=off");
    return s;
  };
  const test::Frame small = test::renderOnce(h, scene, "forward", with("1"), 240, 135);
  const test::Frame large = test::renderOnce(h, scene, "forward", with("8"), 240, 135);
  const test::Frame standard = test::renderOnce(h, scene, "standard", base, 240, 135);
  expectSane(small, "forward splat 1");
  expectSane(large, "forward splat 8");
  const double ws = wrongPct(scene, small), wl = wrongPct(scene, large), wstd = wrongPct(scene, standard);
  std::printf("basic 256^2: forward splat 1 %.2f %%, splat 8 %.2f %%, standard %.2f %%\n", ws, wl, wstd);
  EXPECT_GT(ws, 5.0) << "one-pixel splats of a coarse map leave holes";
  EXPECT_LT(wl, 0.5 * ws);
  // Large splats cover nearly every pixel: what is left is the backward map's own error, plus
  // grazing slopes.
  EXPECT_LT(wl, wstd + 1.0);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// Issue #23: under a grazing light one light texel spans a long stretch of eye pixels, and
// fixed splats left most of the frame dark (columns 64 % wrong, low-sun 87 %). Splats grown to
// the texel's footprint keep them lit; the 0.05 degree sun, where a texel spans more than the
// largest splat, is the method's limit (techniques/reconstruction/README.md).
TEST(Forward, GrownSplatsCoverGrazingTexels) {
  test::GlHarness h;
  for (const std::string id : {"columns", "low-sun"}) {
    const Scene scene = loadScene(id, defaultAssetsDir());
    const test::Frame forward = test::renderOnce(h, scene, "forward", {}, 160, 90);
    const test::Frame standard = test::renderOnce(h, scene, "standard", {}, 160, 90);
    expectSane(forward, "forward on " + id);
    const double wf = wrongPct(scene, forward), wstd = wrongPct(scene, standard);
    // Splats clipped to the screen, not culled with their centre: low-sun 1.6 % (11.5 % when a
    // splat whose sample is off screen was dropped), columns 0.9 % (2.8 %).
    EXPECT_LE(wf, std::max(2.0, wstd)) << id << ": standard " << wstd << " %";
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// The default gathers per eye pixel what Zhang's scatter lights per light texel
// (accumulation/forward_gather.comp): the same visibility, pixel for pixel, holes included.
// Cases: grown splats (a sun, a low sun whose splats are drawn as rectangles, a spot light's
// perspective view), Zhang's fixed splats of a coarse map (holes everywhere), and a footprint of
// two texels (several texels per pixel).
TEST(Forward, GatherLightsWhatTheScatterLights) {
  test::GlHarness h;
  struct Case {
    std::string scene;
    std::vector<std::string> settings;
  };
  const std::vector<Case> cases = {{"basic", {}},
                                   {"low-sun", {}},
                                   {"spotlight", {}},
                                   {"basic", {"shadowmap.size=256", "forward.grow=off", "forward.splat=1"}},
                                   {"columns", {"shadowmap.size=512", "forward.footprint=2"}}};
  for (const Case& c : cases) {
    const Scene scene = loadScene(c.scene, defaultAssetsDir());
    std::vector<std::string> scatter = c.settings;
    scatter.push_back("forward.scatter=on");
    const test::Frame gathered = test::renderOnce(h, scene, "forward", c.settings, 160, 90);
    const test::Frame scattered = test::renderOnce(h, scene, "forward", scatter, 160, 90);
    const std::string what = c.scene + (c.settings.empty() ? "" : " " + c.settings.back());
    expectSane(gathered, what);
    int differ = 0, lit = 0, dark = 0;
    for (int y = 0; y < 90; ++y)
      for (int x = 0; x < 160; ++x) {
        differ += gathered.at(x, y) != scattered.at(x, y);
        (scattered.at(x, y) > 0.5f ? lit : dark) += 1;
      }
    EXPECT_EQ(differ, 0) << what;
    EXPECT_GT(lit, 0) << what;
    EXPECT_GT(dark, 0) << what;
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// A point light through a single focused view (at most 80 degrees off its axis): receivers
// beyond the cone are outside the map, where no texel can reach them; the backward test calls
// them lit and forward mapping now does too (accumulation/forward_splat.glsl, forwardReceiver). Without it
// street was 5.7 % wrong against standard's 0.76 % at 320x180.
TEST(Forward, PixelsOutsideTheMapAreLitAsTheBackwardTestHasThem) {
  test::GlHarness h;
  const Scene scene = loadScene("street", defaultAssetsDir());
  const test::Frame forward = test::renderOnce(h, scene, "forward", {}, 160, 90);
  const test::Frame standard = test::renderOnce(h, scene, "standard", {}, 160, 90);
  expectSane(forward, "forward on street");
  const double wf = wrongPct(scene, forward), wstd = wrongPct(scene, standard);
  std::printf("street: forward %.2f %%, standard %.2f %%\n", wf, wstd);
  EXPECT_LE(wf, std::max(2.0, 2.0 * wstd)) << "standard " << wstd << " %";
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(Reconstruction, HardCasesStayFinite) {
  test::GlHarness h;
  for (const HardCase& hc : hardCases()) {
    Scene scene = loadScene("basic", defaultAssetsDir());
    Camera cam = scene.cameras.front();
    hc.setup(scene, cam);
    h.renderer.setScene(scene);
    for (const std::string preset : {"standard", "silhouette", "forward"}) {
      Viewport vp(makeTechnique(preset, {"shadowmap.size=512"}));
      vp.shownViews = vp.availableViews();  // the debug views must survive the cases too
      FrameInput in;
      in.camera = cam;
      in.width = 160;
      in.height = 90;
      in.cut = true;
      h.renderer.render(in, {&vp});
      const test::Frame f = test::readFrame(h.renderer, vp, in.width, in.height);
      expectSane(f, hc.name + " " + preset);
      const double wrong = wrongPct(scene, f);
      std::printf("%-50s %-10s %.2f %%\n", hc.name.c_str(), preset.c_str(), wrong);
    }
  }
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(Reconstruction, RealScenesStayFinite) {
  const std::filesystem::path shared = std::filesystem::path(SHADOWLAB_SOURCE_DIR) / ".." / "shared" / "scenes-real";
  if (!std::filesystem::exists(shared)) GTEST_SKIP() << "shared/scenes-real not found: " << shared;
  test::GlHarness h;
  for (const std::string id : {"sponza", "engine", "tree"}) {
    const Scene scene = loadScene(id, defaultAssetsDir());
    for (const std::string preset : {"silhouette", "forward"}) {
      const test::Frame f = test::renderOnce(h, scene, preset, {"shadowmap.size=512"}, 160, 90);
      expectSane(f, id + " " + preset);
    }
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace
}  // namespace sl
