// The paged virtual shadow map on llvmpipe (small frames): page marking, the cache, pool
// exhaustion, accuracy against the focused map, and the real glTF scenes staying finite.
#include "metrics/metrics.h"
#include "reference/reference.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <algorithm>
#include <fstream>

namespace sl {
namespace {

constexpr int kVirtualW = 160, kVirtualH = 90;

struct VirtualRun {
  test::Frame frame;
  std::string status;
  long long texels = 0;
  std::vector<std::string> passes;
};

// `frames` frames of one viewport from the scene's first camera (scene already set).
VirtualRun render(test::GlHarness& h, const Scene& scene, const std::string& preset,
                  const std::vector<std::string>& sets, int frames = 1, bool views = false) {
  Viewport vp(makeTechnique(preset, sets));
  if (views) vp.shownViews = vp.availableViews();
  VirtualRun r;
  for (int f = 0; f < frames; ++f) {
    FrameInput in;
    in.camera = scene.cameras.front();
    in.width = kVirtualW;
    in.height = kVirtualH;
    h.renderer.render(in, {&vp});
  }
  r.frame = test::readFrame(h.renderer, vp, kVirtualW, kVirtualH);
  r.status = vp.status();
  r.texels = vp.shadowTexels();
  for (const auto& p : h.renderer.stats().passes) r.passes.push_back(p.name);
  return r;
}

using test::wrongPct;

void expectSane(const test::Frame& f, const std::string& what) {
  EXPECT_EQ(f.nonfinite(), 0) << what;
  for (size_t i = 0; i < f.visibility.size(); i += 2) {
    ASSERT_GE(f.visibility[i], 0.0f) << what;
    ASSERT_LE(f.visibility[i], 1.0f) << what;
  }
}

long long shadowed(const test::Frame& f) {
  long long n = 0;
  for (size_t i = 0; i < f.visibility.size(); i += 2) n += f.visibility[i] < 0.5f && f.position[2 * i + 3] > 0.5f;
  return n;
}

TEST(VirtualShadowMap, MarksPagesDrawsThemAndKeepsThemCached) {
  test::GlHarness h;
  Scene scene = loadScene("columns", defaultAssetsDir());
  h.renderer.setScene(scene);
  const VirtualRun first = render(h, scene, "virtual", {}, 1, true);
  expectSane(first.frame, "first frame");
  EXPECT_NE(std::find(first.passes.begin(), first.passes.end(), "virtual.pages[0]"), first.passes.end());
  EXPECT_NE(first.status.find("cache hits 0"), std::string::npos) << first.status;
  EXPECT_EQ(first.status.find("drawn 0,"), std::string::npos) << first.status;
  EXPECT_GT(shadowed(first.frame), 0);
  // Same light, scene and camera: every page comes from the cache, the image is the same.
  const VirtualRun again = render(h, scene, "virtual", {}, 3);
  EXPECT_NE(again.status.find("drawn 0,"), std::string::npos) << again.status;
  EXPECT_EQ(again.frame.visibility, first.frame.visibility);
  // Without the cache every page is drawn each frame, and the image is still the same.
  const VirtualRun uncached = render(h, scene, "virtual", {"virtual.cache=off"}, 2);
  EXPECT_EQ(uncached.status.find("drawn 0,"), std::string::npos) << uncached.status;
  EXPECT_EQ(uncached.frame.visibility, first.frame.visibility);
  // Texels: the 1920² atlas and the page table (16384 / 128 = 128 pages per side: the finest
  // resident page for each of level 0's).
  EXPECT_EQ(first.texels, 1920LL * 1920 + 128 * 128);
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// The page marking reads world positions alone ("gbuffer.position"): when nothing else that
// runs reads the G-buffer (the bench, the explorer while moving), its pass writes that target
// alone, and the pages, so the image, are the same as with the whole G-buffer drawn.
TEST(VirtualShadowMap, MarkingNeedsOnlyTheGBuffersPositions) {
  test::GlHarness h;
  Scene scene = loadScene("columns", defaultAssetsDir());
  h.renderer.setScene(scene);
  auto visibilityOf = [&](bool keepGBuffer) {
    h.renderer.keepGBuffer = keepGBuffer;
    Viewport vp(makeTechnique("adaptive", {}));
    FrameInput in;
    in.camera = scene.cameras.front();
    in.width = kVirtualW;
    in.height = kVirtualH;
    for (int f = 0; f < 3; ++f) h.renderer.render(in, {&vp});  // edges: last frame's visibility too
    std::vector<std::string> passes;
    for (const auto& p : h.renderer.stats().passes) passes.push_back(p.name);
    EXPECT_NE(std::find(passes.begin(), passes.end(), "gbuffer"), passes.end()) << "keep " << keepGBuffer;
    EXPECT_EQ(h.renderer.hasFreshGBuffer(), keepGBuffer) << "a G-buffer of positions alone is no G-buffer to read back";
    return vp.visibilityTexture()->readFloats(2);
  };
  const std::vector<float> positionsOnly = visibilityOf(false);
  const std::vector<float> whole = visibilityOf(true);
  h.renderer.keepGBuffer = true;
  ASSERT_EQ(positionsOnly.size(), whole.size());
  EXPECT_EQ(positionsOnly, whole);
  long long shadowedPixels = 0;
  for (size_t i = 0; i < whole.size(); i += 2) shadowedPixels += whole[i] < 0.5f;
  EXPECT_GT(shadowedPixels, 100) << "the case has shadows whose pages the marking asked for";
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(VirtualShadowMap, MovingTheLightRedrawsThePages) {
  test::GlHarness h;
  Scene scene = loadScene("columns", defaultAssetsDir());
  h.renderer.setScene(scene);
  Viewport vp(makeTechnique("virtual"));
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = kVirtualW;
  in.height = kVirtualH;
  h.renderer.render(in, {&vp});
  h.renderer.render(in, {&vp});
  EXPECT_NE(vp.status().find("drawn 0,"), std::string::npos) << vp.status();
  scene.light.direction = glm::normalize(scene.light.direction + glm::vec3(0.3f, 0.0f, -0.2f));
  h.renderer.render(in, {&vp});
  EXPECT_EQ(vp.status().find("drawn 0,"), std::string::npos) << vp.status();
  const std::vector<float> moved = vp.visibilityTexture()->readFloats(2);
  // What a viewport that never saw the old light renders: stale pages would differ from it.
  EXPECT_EQ(moved, render(h, scene, "virtual", {}).frame.visibility);
}

// Moving objects drop only the pages under them (then and now): the others are served from the
// cache, and the image is what a viewport that never saw the earlier times renders (no stale
// page). The light view is fitted to the scene's whole motion, so it does not move with them.
TEST(VirtualShadowMap, MovingObjectsRedrawOnlyThePagesUnderThem) {
  test::GlHarness h;
  const Scene scene = loadScene("moving", defaultAssetsDir());
  h.renderer.setScene(scene);
  auto frameAt = [&](Viewport& vp, double t) {
    FrameInput in;
    in.camera = scene.cameras.front();
    in.time = t;
    in.width = kVirtualW;
    in.height = kVirtualH;
    h.renderer.render(in, {&vp});
  };
  auto number = [](const std::string& status, const std::string& key) {
    const size_t at = status.find(key);
    return at == std::string::npos ? -1 : std::stoi(status.substr(at + key.size()));
  };
  Viewport vp(makeTechnique("virtual"));
  frameAt(vp, 0.0);
  frameAt(vp, 0.0);
  EXPECT_NE(vp.status().find("drawn 0,"), std::string::npos) << "same time: everything cached; " << vp.status();
  for (double t : {0.25, 0.5}) {
    frameAt(vp, t);
    const std::string status = vp.status();
    EXPECT_NE(status.find("dropped under moving objects"), std::string::npos) << status;
    EXPECT_GT(number(status, "drawn "), 0) << status;
    EXPECT_GT(number(status, "cache hits "), 0) << "pages away from the moving objects stay; " << status;
  }
  const std::vector<float> moved = vp.visibilityTexture()->readFloats(2);
  Viewport fresh(makeTechnique("virtual"));
  frameAt(fresh, 0.5);
  const std::vector<float> expected = fresh.visibilityTexture()->readFloats(2);
  ASSERT_EQ(moved.size(), expected.size());
  // (visibility, confidence): the same visibility; the confidence, from the texel position in
  // the atlas, may round differently where a page sits in another tile.
  for (size_t i = 0; i < moved.size(); i += 2) {
    ASSERT_EQ(moved[i], expected[i]) << "pixel " << i / 2;
    ASSERT_NEAR(moved[i + 1], expected[i + 1], 1e-3f) << "pixel " << i / 2;
  }
  test::Frame f = test::readFrame(h.renderer, vp, kVirtualW, kVirtualH);
  expectSane(f, "moving");
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(VirtualShadowMap, TinyPoolIsReportedAndDegradesToCoarserPages) {
  test::GlHarness h;
  Scene scene = loadScene("columns", defaultAssetsDir());
  h.renderer.setScene(scene);
  const VirtualRun full = render(h, scene, "virtual", {});
  EXPECT_EQ(full.status.find("exhausted"), std::string::npos) << full.status;
  const VirtualRun tiny = render(h, scene, "virtual", {"virtual.pool=256"}, 2, true);  // 2 x 2 tiles
  expectSane(tiny.frame, "tiny pool");
  EXPECT_NE(tiny.status.find("pool exhausted"), std::string::npos) << tiny.status;
  EXPECT_NE(tiny.status.find("in 4 tiles"), std::string::npos) << tiny.status;
  // Coarser, so less accurate, but still a shadow map of the scene and not garbage.
  const double wrongFull = wrongPct(scene, full.frame), wrongTiny = wrongPct(scene, tiny.frame);
  const VirtualRun uniform = render(h, scene, "uniform", {"shadowmap.size=256"});
  std::printf("columns %dx%d: virtual %.3f %%, pool of 4 tiles %.3f %%, uniform 256² %.3f %%\n", kVirtualW, kVirtualH,
              wrongFull, wrongTiny, wrongPct(scene, uniform.frame));
  EXPECT_LT(wrongFull, wrongTiny);
  EXPECT_LE(wrongTiny, wrongPct(scene, uniform.frame) + 0.5);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(VirtualShadowMap, AsAccurateAsAFocused4096MapOnColumnsAndTerrain) {
  test::GlHarness h;
  for (const char* name : {"columns", "terrain"}) {
    Scene scene = loadScene(name, defaultAssetsDir());
    h.renderer.setScene(scene);
    const VirtualRun standard = render(h, scene, "standard", {"shadowmap.size=4096"});
    const VirtualRun virt = render(h, scene, "virtual", {});
    expectSane(virt.frame, name);
    const double ws = wrongPct(scene, standard.frame), wv = wrongPct(scene, virt.frame);
    std::printf("%s %dx%d: standard 4096² %.3f %% (%lld texels), virtual %.3f %% (%lld texels; %s)\n", name, kVirtualW,
                kVirtualH, ws, standard.texels, wv, virt.texels, virt.status.c_str());
    EXPECT_LE(wv, ws + 0.05) << name;
    EXPECT_LE(virt.texels * 4, standard.texels + 4 * 65536) << name;
  }
}

// The hard scenes are in techniques/layouts/hard_cases_gl_test.cpp (virtual is in its
// list); here the real glTF scenes, when shared/scenes-real is there.
// "requested N" from the layout's status line.
int requestedPages(const std::string& status) {
  const size_t at = status.find("requested ");
  return at == std::string::npos ? -1 : std::stoi(status.substr(at + 10));
}

// The termination criteria over one page machinery (the survey: "algorithms mainly differ in
// termination criteria"): adaptive (edges) asks for fewer pages than resolution matching once it
// has a frame's shadow edges, for the same shadows; on its first frame it asks as much; tiled
// (distance, by world size) is as accurate here.
TEST(VirtualShadowMap, CriteriaAskForDifferentPagesForTheSameShadows) {
  test::GlHarness h;
  const Scene scene = loadScene("columns", defaultAssetsDir());
  h.renderer.setScene(scene);
  const VirtualRun matched = render(h, scene, "virtual", {}, 2);
  const VirtualRun adaptiveFirst = render(h, scene, "adaptive", {}, 1);
  const VirtualRun adaptive = render(h, scene, "adaptive", {}, 2);
  const VirtualRun tiled = render(h, scene, "tiled", {}, 2);
  const int m = requestedPages(matched.status), a1 = requestedPages(adaptiveFirst.status);
  const int a = requestedPages(adaptive.status), t = requestedPages(tiled.status);
  ASSERT_GT(m, 0) << matched.status;
  EXPECT_EQ(a1, m) << "no edges known on the first frame: every pixel asks";
  EXPECT_LT(a, m) << adaptive.status;
  EXPECT_GT(t, 0) << tiled.status;
  const double wrongMatched = wrongPct(scene, matched.frame);
  EXPECT_LE(wrongPct(scene, adaptive.frame), wrongMatched + 0.01);
  EXPECT_LE(wrongPct(scene, tiled.frame), wrongMatched + 0.01);
  expectSane(adaptive.frame, "adaptive");
  expectSane(tiled.frame, "tiled");
}

// Tiled maps' depth-discontinuity term (Arvo 2004): away from the bends and steps of the light's
// depth (last frame's pages) a pixel asks edge_coarsen levels coarser than its distance level.
// On terrain that serves the same shadows from fewer pages than the distance heuristic alone
// (virtual.depth_step=0); on the first frame, with no page drawn yet, every pixel keeps its level.
TEST(VirtualShadowMap, TiledRefinesOnlyNearTheLightDepthsDiscontinuities) {
  test::GlHarness h;
  const Scene scene = loadScene("terrain", defaultAssetsDir());
  h.renderer.setScene(scene);
  const VirtualRun distanceOnly = render(h, scene, "tiled", {"virtual.depth_step=0"}, 2);
  const VirtualRun first = render(h, scene, "tiled", {}, 1);
  const VirtualRun tiled = render(h, scene, "tiled", {}, 2);
  const int d = requestedPages(distanceOnly.status), f = requestedPages(first.status);
  const int t = requestedPages(tiled.status);
  std::printf("terrain %dx%d: tiled %d pages (%.3f %%), distance alone %d (%.3f %%)\n", kVirtualW, kVirtualH, t,
              wrongPct(scene, tiled.frame), d, wrongPct(scene, distanceOnly.frame));
  EXPECT_EQ(f, d) << "no page drawn yet: no discontinuity known, every pixel keeps its level";
  EXPECT_LT(t, d) << tiled.status;
  EXPECT_LE(wrongPct(scene, tiled.frame), wrongPct(scene, distanceOnly.frame) + 0.01);
  expectSane(tiled.frame, "tiled");
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

// Fitted virtual shadow maps: the same footprints, gathered into a grid and fitted into a
// quadtree on the CPU. Its leaves partition the sampled area and are never coarser than a pixel
// asked for, so it is as accurate as resolution matching; the status reports the CPU fit; a
// pool too small for the leaves degrades as for the other criteria.
TEST(VirtualShadowMap, FittedCriterionFitsAQuadtreeOnTheCpu) {
  test::GlHarness h;
  const Scene scene = loadScene("columns", defaultAssetsDir());
  h.renderer.setScene(scene);
  const VirtualRun matched = render(h, scene, "virtual", {}, 2);
  const VirtualRun fitted = render(h, scene, "fitted-virtual", {}, 2, true);
  expectSane(fitted.frame, "fitted-virtual");
  EXPECT_NE(fitted.status.find("quadtree fitted on the CPU"), std::string::npos) << fitted.status;
  const size_t at = fitted.status.find("nodes, ");
  ASSERT_NE(at, std::string::npos) << fitted.status;
  EXPECT_EQ(std::stoi(fitted.status.substr(at + 7)), requestedPages(fitted.status)) << "leaves are the pages asked for";
  EXPECT_GT(requestedPages(fitted.status), 0) << fitted.status;
  const double wrongMatched = wrongPct(scene, matched.frame), wrongFitted = wrongPct(scene, fitted.frame);
  std::printf("columns %dx%d: virtual %.3f %% (%s)\n  fitted %.3f %% (%s)\n", kVirtualW, kVirtualH, wrongMatched,
              matched.status.c_str(), wrongFitted, fitted.status.c_str());
  EXPECT_LE(wrongFitted, wrongMatched + 0.01);
  EXPECT_EQ(matched.status.find("quadtree"), std::string::npos) << "only the fitted criterion fits a quadtree";
  const VirtualRun tiny = render(h, scene, "fitted-virtual", {"virtual.pool=256"}, 2);
  expectSane(tiny.frame, "fitted-virtual, tiny pool");
  EXPECT_NE(tiny.status.find("pool exhausted"), std::string::npos) << tiny.status;
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// The requested-resolution view shows what each criterion asked for (the marking pass's own
// function), not the footprint under every criterion: tiled asks finer than virtual on columns'
// ground, so the two views differ over much of the picture.
TEST(VirtualShadowMap, RequestedResolutionViewFollowsTheCriterion) {
  test::GlHarness h;
  const Scene scene = loadScene("columns", defaultAssetsDir());
  h.renderer.setScene(scene);
  auto requestedView = [&](const std::string& preset) {
    Viewport vp(makeTechnique(preset, {}));
    vp.shownViews = {"requested-resolution"};
    FrameInput in;
    in.camera = scene.cameras.front();
    in.width = kVirtualW;
    in.height = kVirtualH;
    for (int f = 0; f < 2; ++f) h.renderer.render(in, {&vp});
    EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
    const Texture2D* view = vp.viewTexture("requested-resolution");
    return view ? view->readRgba8() : std::vector<unsigned char>{};
  };
  const std::vector<unsigned char> matched = requestedView("virtual"), tiled = requestedView("tiled");
  ASSERT_EQ(matched.size(), size_t(4) * kVirtualW * kVirtualH);
  ASSERT_EQ(tiled.size(), matched.size());
  int differing = 0;
  for (size_t i = 0; i < matched.size(); i += 4)
    differing += std::abs(int(matched[i]) - int(tiled[i])) + std::abs(int(matched[i + 1]) - int(tiled[i + 1])) > 24;
  EXPECT_GT(differing, kVirtualW * kVirtualH / 10) << "the view shows the same levels under both criteria";
}

// Per-page instance culling (shadowmap.cull_instances): an instance outside a page's square is
// not drawn into it, and the map is the same texel for texel.
TEST(VirtualShadowMap, PagesCullInstancesWithoutChangingTheMap) {
  test::GlHarness h;
  const Scene scene = loadScene("terrain", defaultAssetsDir());
  h.renderer.setScene(scene);
  const VirtualRun on = render(h, scene, "virtual", {"shadowmap.cull_instances=on"});
  const VirtualRun off = render(h, scene, "virtual", {"shadowmap.cull_instances=off"});
  ASSERT_EQ(on.frame.visibility.size(), off.frame.visibility.size());
  EXPECT_EQ(on.frame.visibility, off.frame.visibility);
  EXPECT_GT(shadowed(on.frame), 0) << "nothing shadowed: the comparison would prove nothing";
}

TEST(VirtualShadowMap, RealScenesStayFinite) {
  test::GlHarness h;
  int ran = 0;
  for (const char* name : {"sponza", "engine", "tree"}) {
    Scene scene;
    try {
      scene = loadScene(name, defaultAssetsDir());
    } catch (const std::exception& e) {
      if (std::string(e.what()).find("scenes-real") != std::string::npos) continue;
      throw;
    }
    h.renderer.setScene(scene);
    for (const char* preset : {"virtual", "fitted-virtual"}) {
      const VirtualRun r = render(h, scene, preset, {}, 2, true);
      expectSane(r.frame, std::string(name) + " " + preset);
      std::printf("%s %s: %s\n", name, preset, r.status.c_str());
    }
    ++ran;
  }
  if (ran == 0) GTEST_SKIP() << "shared/scenes-real not found: the real scenes were not rendered";
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace
}  // namespace sl

namespace sl {
namespace {

// virtual.async_marks: pages allocated from the newest marks that have arrived instead of this
// frame's. On llvmpipe, which has run the marking by the time the copy is polled, that is this
// frame's, so every frame (a camera moving between frames, every criterion, a switch to the
// fitted grid's buffer of another size) must be the same image as waiting for the marks; wrong
// bytes, a stale ring or zeros would leave the coarsest page and change it.
TEST(VirtualShadowMap, AsyncMarksGiveTheSameFramesWhereTheyArriveInTime) {
  test::GlHarness h;
  const Scene scene = loadScene("columns", defaultAssetsDir());
  h.renderer.setScene(scene);
  Camera moved = scene.cameras.front();
  moved.position += glm::vec3(1.5f, 0.5f, -1.0f);
  const std::vector<Camera> cameras = {scene.cameras.front(), scene.cameras.front(), moved, moved};
  for (const char* preset : {"virtual", "tiled", "adaptive", "fitted-virtual"}) {
    std::vector<std::vector<float>> frames[2];
    std::string status[2];
    for (int async = 0; async < 2; ++async) {
      Viewport vp(makeTechnique(preset, {std::string("virtual.async_marks=") + (async ? "on" : "off")}));
      for (const Camera& camera : cameras) {
        FrameInput in;
        in.camera = camera;
        in.width = kVirtualW;
        in.height = kVirtualH;
        h.renderer.render(in, {&vp});
        frames[async].push_back(test::readFrame(h.renderer, vp, kVirtualW, kVirtualH).visibility);
      }
      status[async] = vp.status();
      if (std::string(preset) == "virtual" && async) {  // the criterion's buffer changes size
        vp.technique.params.setAssignment("virtual.criterion=fitted");
        FrameInput in;
        in.camera = moved;
        in.width = kVirtualW;
        in.height = kVirtualH;
        h.renderer.render(in, {&vp});
        const test::Frame fitted = test::readFrame(h.renderer, vp, kVirtualW, kVirtualH);
        expectSane(fitted, "virtual switched to fitted");
        EXPECT_NE(vp.status().find("quadtree"), std::string::npos) << vp.status();
        EXPECT_GT(requestedPages(vp.status()), 1) << "the fitted grid's marks arrived: " << vp.status();
      }
    }
    for (size_t f = 0; f < cameras.size(); ++f) EXPECT_EQ(frames[1][f], frames[0][f]) << preset << ", frame " << f;
    // The same pages requested, resident, drawn and cached (the fitted criterion's CPU time aside).
    const auto untimed = [](const std::string& st) {
      return st.substr(0, st.find(" ms") == std::string::npos ? st.size() : st.rfind(',', st.find(" ms")));
    };
    EXPECT_EQ(untimed(status[1]), untimed(status[0])) << preset;
    EXPECT_GT(requestedPages(status[1]), 1) << preset << ": " << status[1];
  }
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace
}  // namespace sl
