// Pixel-correct shadow maps (Scherzer et al. 2007) on llvmpipe at small sizes: convergence to the
// ray-traced reference, history reset on cuts, NaN safety under violent camera motion, no ghost
// shadows behind a moving caster, debug views culled unless shown, hot reload of the update shader.
#include "gl_test_util.h"

#include "accumulation/pixel_correct.h"
#include "metrics/metrics.h"
#include "bench/reference_cache.h"
#include "reference/reference.h"
#include "technique.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace sl {

using test::Frame;
using test::GlHarness;

namespace {

struct Comparison {
  ErrorMetrics metrics;
  std::vector<float> reference;
  std::vector<uint8_t> valid;
};

// One tracer per scene and time for the whole test binary: building the BVH for every
// comparison only costs time.
// Keyed by the scene's content, not its address: tests' scenes live on the stack.
const ReferenceTracer& tracerFor(const Scene& scene, double time) {
  static std::map<std::pair<std::string, double>, std::unique_ptr<ReferenceTracer>> tracers;
  auto& slot = tracers[{sceneContentHash(scene), time}];
  if (!slot) slot = std::make_unique<ReferenceTracer>(scene, time);
  return *slot;
}

Comparison compareToReference(const Scene& scene, const Frame& f, double time) {
  Comparison c;
  const ReferenceTracer& tracer = tracerFor(scene, time);
  ReferenceOptions opts;
  opts.time = time;
  c.reference = tracer.visibility(f.gbuffer(), opts);
  const size_t n = static_cast<size_t>(f.width) * f.height;
  std::vector<float> vis(n);
  c.valid.resize(n);
  for (size_t i = 0; i < n; ++i) {
    vis[i] = f.visibility[2 * i];
    c.valid[i] = f.position[4 * i + 3] > 0.5f;
  }
  c.metrics = compareVisibility(vis.data(), c.reference.data(), c.valid.data(), n);
  return c;
}

FrameInput frameInput(const Camera& cam, int w, int h, double time = 0.0, bool cut = false) {
  FrameInput in;
  in.camera = cam;
  in.width = w;
  in.height = h;
  in.time = time;
  in.cut = cut;
  return in;
}

bool hasPass(const Renderer& r, const std::string& name) {
  for (const auto& p : r.stats().passes)
    if (p.name == name) return true;
  return false;
}

}  // namespace

TEST(PixelCorrect, RegisteredWithItsParametersPresetsAndViews) {
  Technique t = makeTechnique("pixel-correct");
  EXPECT_EQ(t.accumulation->id(), "pixel-correct");
  EXPECT_EQ(t.representation->id(), "depth-nearest");
  EXPECT_EQ(t.layout->id(), "focused");
  for (const char* key : {"pc.m", "pc.adaptive", "pc.m_moving", "pc.m_step", "pc.jitter", "pc.jitter_amplitude",
                          "pc.rotate", "pc.rotation_deg", "pc.pause_jitter", "pc.disocclusion", "pc.history_format",
                          "pc.reject", "pc.reject_confidence", "pc.reject_neighbours", "pc.warmup"})
    EXPECT_TRUE(t.params.has(key)) << key;
  EXPECT_EQ(t.params.choice("pc.history_format"), "fp16");
  Technique pcf = makeTechnique("pixel-correct-pcf", {"pc.history_format=fp32"});
  EXPECT_EQ(pcf.representation->id(), "depth-pcf");
  EXPECT_EQ(pcf.params.choice("pc.history_format"), "fp32");
  EXPECT_THROW(makeTechnique("pixel-correct", {"pc.m=0"}), ParamError);

  Viewport vp(t);
  auto views = vp.availableViews();
  for (const char* v : {"confidence", "history", "disocclusion"})
    EXPECT_NE(std::find(views.begin(), views.end(), v), views.end()) << v;

  // Halton: radical inverse; the jitter stays inside the declared ranges and never repeats early.
  EXPECT_FLOAT_EQ(halton(1, 2), 0.5f);
  EXPECT_FLOAT_EQ(halton(3, 2), 0.75f);
  EXPECT_FLOAT_EQ(halton(2, 3), 2.0f / 3.0f);
  t.params.set("pc.jitter_amplitude", 2.0);
  t.params.set("pc.rotation_deg", 20.0);
  for (int i = 0; i < 64; ++i) {
    LayoutJitter j = pixelCorrectJitter(t.params, i);
    EXPECT_LE(std::abs(j.offsetTexels.x), 1.0f);
    EXPECT_LE(std::abs(j.offsetTexels.y), 1.0f);
    EXPECT_LE(std::abs(j.rotationRad), glm::radians(20.0f) + 1e-6f);
    LayoutJitter k = pixelCorrectJitter(t.params, i + 1);
    EXPECT_NE(j.offsetTexels, k.offsetTexels);
  }
  // pc.jitter_moving off: the layout's own rasterization while the camera moves, jitter at rest.
  PixelCorrectState state;
  EXPECT_NE(state.jitter(t.params, true).offsetTexels, glm::vec2(0.0f));  // default: the paper
  t.params.set("pc.jitter_moving", 0);
  EXPECT_EQ(state.jitter(t.params, true).offsetTexels, glm::vec2(0.0f));
  EXPECT_EQ(state.jitter(t.params, true).rotationRad, 0.0f);
  EXPECT_NE(state.jitter(t.params, false).offsetTexels, glm::vec2(0.0f));
  t.params.set("pc.jitter", 0);
  t.params.set("pc.rotate", 0);
  EXPECT_EQ(pixelCorrectJitter(t.params, 5).offsetTexels, glm::vec2(0.0f));
  EXPECT_EQ(pixelCorrectJitter(t.params, 5).rotationRad, 0.0f);

  // Adaptive exponent: low while moving or without history, +step per still frame, capped.
  ParamSet& p = t.params;
  EXPECT_FLOAT_EQ(pixelCorrectNextExponent(p, 0.0f, false, false), 15.0f);  // warm-up: fresh history at full m
  p.set("pc.warmup", 0);
  EXPECT_FLOAT_EQ(pixelCorrectNextExponent(p, 0.0f, false, false), 3.0f);
  EXPECT_FLOAT_EQ(pixelCorrectNextExponent(p, 3.0f, false, true), 3.1f);
  EXPECT_FLOAT_EQ(pixelCorrectNextExponent(p, 14.95f, false, true), 15.0f);
  EXPECT_FLOAT_EQ(pixelCorrectNextExponent(p, 9.0f, true, true), 3.0f);
  p.set("pc.adaptive", 0);
  EXPECT_FLOAT_EQ(pixelCorrectNextExponent(p, 3.0f, true, true), 15.0f);
}

// The paper's claim: with a still camera the history converges to pixel-correct shadows. Empty
// history, 60 frames, 512^2 focused map at 320x180 on `basic`, against the Embree reference.
TEST(PixelCorrect, ConvergesToTheReferenceWithAStillCamera) {
  GlHarness h;
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  const int w = 320, hgt = 180;
  FrameInput in = frameInput(scene.cameras.front(), w, hgt);

  Viewport standard(makeTechnique("standard", {"shadowmap.size=512"}));
  h.renderer.render(in, {&standard});
  Comparison ref = compareToReference(scene, test::readFrame(h.renderer, standard, w, hgt), 0.0);

  Viewport pc(makeTechnique("pixel-correct", {"shadowmap.size=512"}));
  std::vector<double> wrong;
  for (int f = 0; f < 60; ++f) {
    h.renderer.render(in, {&pc});
    if (f == 0 || f % 10 == 9) {
      Frame fr = test::readFrame(h.renderer, pc, w, hgt);
      wrong.push_back(compareToReference(scene, fr, 0.0).metrics.wrongPixelPct);
    }
  }
  Frame last = test::readFrame(h.renderer, pc, w, hgt);
  Comparison c = compareToReference(scene, last, 0.0);
  std::printf("[pixel-correct] basic 320x180, 512^2: standard wrong %.3f%% | pixel-correct frame 1..60:",
              ref.metrics.wrongPixelPct);
  for (double x : wrong) std::printf(" %.3f%%", x);
  std::printf(" | final wrong %.3f%% (false shadow %.3f%%, false light %.3f%%), rmse %.4f, %s\n",
              c.metrics.wrongPixelPct, c.metrics.falseShadowPct, c.metrics.falseLightPct, c.metrics.rmse,
              pc.accumulation->status().c_str());
  EXPECT_EQ(last.nonfinite(), 0);
  EXPECT_LT(c.metrics.wrongPixelPct, 0.1);
  EXPECT_LT(c.metrics.wrongPixelPct, ref.metrics.wrongPixelPct);
  EXPECT_LT(c.metrics.rmse, ref.metrics.rmse);
  EXPECT_EQ(glDebugErrorCount(), 0);
  EXPECT_TRUE(h.shaders.errors().empty());
}

// pc.keep_best (the m -> infinity limit of eq. 6) converges faster than the weighted mean.
TEST(PixelCorrect, KeepBestConvergesFasterThanTheWeightedMean) {
  GlHarness h;
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  const int w = 320, hgt = 180;
  FrameInput in = frameInput(scene.cameras.front(), w, hgt);
  Viewport mean(makeTechnique("pixel-correct", {"shadowmap.size=512"}));
  Viewport best(makeTechnique("pixel-correct", {"shadowmap.size=512", "pc.keep_best=on"}));
  for (int f = 0; f < 40; ++f) h.renderer.render(in, {&mean, &best});
  Frame fm = test::readFrame(h.renderer, mean, w, hgt), fb = test::readFrame(h.renderer, best, w, hgt);
  const double wrongMean = compareToReference(scene, fm, 0.0).metrics.wrongPixelPct;
  const double wrongBest = compareToReference(scene, fb, 0.0).metrics.wrongPixelPct;
  std::printf("[pixel-correct] basic, 40 frames: weighted mean %.3f%%, keep best %.3f%%\n", wrongMean, wrongBest);
  EXPECT_EQ(fb.nonfinite(), 0);
  EXPECT_LT(wrongBest, wrongMean);
  EXPECT_LT(wrongBest, 0.05);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// The paper's large-scene case: over a LiSPSM layout the history converges where a focused
// map cannot (columns: perspective aliasing near the viewer), below standard at 64x the texels.
TEST(PixelCorrect, OverLispsmConvergesOnColumnsBelowStandardAt4096) {
  GlHarness h;
  Scene scene = loadScene("columns", defaultAssetsDir());
  h.renderer.setScene(scene);
  const int w = 320, hgt = 180;
  FrameInput in = frameInput(scene.cameras.front(), w, hgt);
  Viewport big(makeTechnique("standard", {"shadowmap.size=4096"}));
  h.renderer.render(in, {&big});
  Comparison ref4096 = compareToReference(scene, test::readFrame(h.renderer, big, w, hgt), 0.0);
  Viewport pc(makeTechnique("pixel-correct-lispsm", {"shadowmap.size=512"}));
  for (int f = 0; f < 60; ++f) h.renderer.render(in, {&pc});
  Frame last = test::readFrame(h.renderer, pc, w, hgt);
  Comparison c = compareToReference(scene, last, 0.0);
  std::printf("[pixel-correct-lispsm] columns 320x180, 512^2, 60 frames: wrong %.3f%% (standard 4096^2: %.3f%%)\n",
              c.metrics.wrongPixelPct, ref4096.metrics.wrongPixelPct);
  EXPECT_EQ(last.nonfinite(), 0);
  EXPECT_LT(c.metrics.wrongPixelPct, 0.1);
  EXPECT_LT(c.metrics.wrongPixelPct, ref4096.metrics.wrongPixelPct);
  EXPECT_EQ(glDebugErrorCount(), 0);
  EXPECT_TRUE(h.shaders.errors().empty());
}

// pc.while_moving=test: while the camera moves the viewport shows the layout's own, unjittered
// test (exactly what `standard` shows); at rest it accumulates again.
TEST(PixelCorrect, WhileMovingTestShowsThePlainTestThenAccumulates) {
  GlHarness h;
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  const int w = 160, hgt = 90;
  Viewport pc(makeTechnique("pixel-correct-at-rest", {"shadowmap.size=256"}));
  Viewport standard(makeTechnique("standard", {"shadowmap.size=256"}));
  Camera cam = scene.cameras.front();
  auto differing = [&](const Viewport& a, const Viewport& b) {
    auto va = a.visibilityTexture()->readFloats(2), vb = b.visibilityTexture()->readFloats(2);
    int n = 0;
    for (size_t i = 0; i < va.size(); i += 2) n += va[i] != vb[i];
    return n;
  };
  for (int f = 0; f < 12; ++f) h.renderer.render(frameInput(cam, w, hgt), {&pc, &standard});
  EXPECT_GT(differing(pc, standard), 0);  // accumulated at rest
  for (int f = 0; f < 3; ++f) {
    cam.position += glm::vec3(0.02f, 0.0f, -0.015f);
    h.renderer.render(frameInput(cam, w, hgt), {&pc, &standard});
    EXPECT_EQ(differing(pc, standard), 0) << "moving frame " << f;
    EXPECT_EQ(pc.lightSpace.primary().viewProj, standard.lightSpace.primary().viewProj);
    EXPECT_NE(pc.accumulation->status().find("plain test"), std::string::npos) << pc.accumulation->status();
  }
  for (int f = 0; f < 12; ++f) h.renderer.render(frameInput(cam, w, hgt), {&pc, &standard});
  EXPECT_GT(differing(pc, standard), 0);  // and at rest again
  EXPECT_NE(pc.accumulation->status().find("keep best"), std::string::npos) << pc.accumulation->status();
  EXPECT_EQ(test::readFrame(h.renderer, pc, w, hgt).nonfinite(), 0);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// A cut forgets everything: the first frame after it shows this frame's raw test exactly.
TEST(PixelCorrect, CameraCutResetsTheHistory) {
  GlHarness h;
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  const int w = 160, hgt = 90;
  Viewport pc(makeTechnique("pixel-correct", {"shadowmap.size=256"}));
  Camera cam = scene.cameras.front();
  for (int f = 0; f < 12; ++f) h.renderer.render(frameInput(cam, w, hgt), {&pc});
  // Accumulated: the shown visibility is not the raw test any more.
  auto acc = pc.visibilityTexture()->readFloats(2), raw = pc.rawVisibilityTexture()->readFloats(2);
  int differ = 0;
  for (size_t i = 0; i < acc.size(); i += 2) differ += acc[i] != raw[i];
  EXPECT_GT(differ, 0);

  cam.position += glm::vec3(0.7f, 0.3f, -0.4f);
  h.renderer.render(frameInput(cam, w, hgt, 0.0, true), {&pc});
  acc = pc.visibilityTexture()->readFloats(2);
  raw = pc.rawVisibilityTexture()->readFloats(2);
  differ = 0;
  for (size_t i = 0; i < acc.size(); i += 2) differ += acc[i] != raw[i];
  EXPECT_EQ(differ, 0);
  EXPECT_EQ(pc.accumulation->status().find("frame 1") != std::string::npos, true) << pc.accumulation->status();

  // And accumulation starts again on the next frame.
  h.renderer.render(frameInput(cam, w, hgt), {&pc});
  EXPECT_NE(pc.accumulation->status().find("frame 2"), std::string::npos) << pc.accumulation->status();
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// Violent motion: spins, jumps through geometry, a far plane that cuts the scene. History taps
// land off-screen, behind the previous camera and beyond its far plane: never NaN or Inf.
TEST(PixelCorrect, NoNonFiniteValuesUnderFastCameraMotion) {
  GlHarness h;
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  const int w = 160, hgt = 90;
  for (const char* format : {"fp16", "fp32"}) {
    Viewport pc(makeTechnique("pixel-correct", {"shadowmap.size=256", std::string("pc.history_format=") + format}));
    Camera base = scene.cameras.front();
    glm::vec3 center = base.target;
    float radius = glm::length(base.position - base.target);
    long long nonfinite = 0;
    for (int f = 0; f < 24; ++f) {
      Camera cam = base;
      float a = f * 1.7f;  // ~100 degrees per frame around the target
      float r = (f % 3 == 0) ? radius * 0.05f : radius * (0.5f + 0.25f * (f % 4));
      cam.position = center + glm::vec3(std::cos(a) * r, 0.3f + (f % 5) * 0.8f, std::sin(a) * r);
      if (f % 4 == 1) cam.target = cam.position + (cam.position - center);  // looking away
      cam.farPlane = (f % 2) ? radius * 0.8f : 100.0f;                      // far plane through the scene
      cam.nearPlane = (f % 3 == 2) ? 1.0f : 0.1f;
      h.renderer.render(frameInput(cam, w, hgt), {&pc});
      nonfinite += test::readFrame(h.renderer, pc, w, hgt).nonfinite();
    }
    EXPECT_EQ(nonfinite, 0) << format;
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
  EXPECT_TRUE(h.shaders.errors().empty());
}

// A moving caster must not leave a ghost shadow where it was: scene `moving` at 30 frames per
// second, compared with the reference at the last frame, in particular where the box's shadow
// was some frames earlier and the ground is now lit.
TEST(PixelCorrect, MovingBoxLeavesNoGhostShadow) {
  GlHarness h;
  Scene scene = loadScene("moving", defaultAssetsDir());
  h.renderer.setScene(scene);
  const int w = 320, hgt = 180;
  Camera cam = scene.cameras.front();
  cam.position = glm::vec3(1.0f, 6.0f, 6.0f);  // looking down on the box and its shadow
  cam.target = glm::vec3(0.5f, 0.0f, 0.5f);
  Viewport pc(makeTechnique("pixel-correct", {"shadowmap.size=512"}));
  Viewport standard(makeTechnique("standard", {"shadowmap.size=512"}));
  Viewport noReject(makeTechnique("pixel-correct", {"shadowmap.size=512", "pc.reject=1"}));
  Viewport best(makeTechnique("pixel-correct-at-rest", {"shadowmap.size=512"}));  // pc.keep_best
  const int frames = 48;
  const std::vector<int> gaps = {2, 4, 8, 16};
  std::map<int, std::vector<float>> earlierRef;
  Comparison pcCmp, stdCmp, nrCmp, bestCmp;
  double t = 0;
  for (int f = 0; f < frames; ++f) {
    t = 1.0 + f / 30.0;  // the box accelerates through the middle of its swing (t = 2)
    h.renderer.render(frameInput(cam, w, hgt, t), {&pc, &standard, &noReject, &best});
    for (int g : gaps)
      if (f == frames - 1 - g)
        earlierRef[g] = compareToReference(scene, test::readFrame(h.renderer, pc, w, hgt), t).reference;
    if (f == frames - 1) {
      pcCmp = compareToReference(scene, test::readFrame(h.renderer, pc, w, hgt), t);
      stdCmp = compareToReference(scene, test::readFrame(h.renderer, standard, w, hgt), t);
      nrCmp = compareToReference(scene, test::readFrame(h.renderer, noReject, w, hgt), t);
      bestCmp = compareToReference(scene, test::readFrame(h.renderer, best, w, hgt), t);
    }
  }
  // The area the box's shadow left: in shadow `gap` frames ago, lit now (the ground is static).
  auto leftArea = [&](const Viewport& vp, int gap) {
    auto vis = vp.visibilityTexture()->readFloats(2);
    long long area = 0, wrong = 0;
    for (size_t i = 0; i < pcCmp.reference.size(); ++i) {
      if (!pcCmp.valid[i] || earlierRef[gap][i] > 0.5f || pcCmp.reference[i] < 0.5f) continue;
      ++area;
      wrong += std::abs(vis[2 * i] - pcCmp.reference[i]) > kWrongThreshold;
    }
    return std::make_pair(area, wrong);
  };
  std::printf(
      "[pixel-correct] moving 320x180, 512^2, t=%.2f: wrong standard %.3f%%, pixel-correct %.3f%%, "
      "without rejection %.3f%%, keep best %.3f%%\n",
      t, stdCmp.metrics.wrongPixelPct, pcCmp.metrics.wrongPixelPct, nrCmp.metrics.wrongPixelPct,
      bestCmp.metrics.wrongPixelPct);
  for (int g : gaps) {
    auto [area, ghost] = leftArea(pc, g);
    auto [area2, ghostNoReject] = leftArea(noReject, g);
    auto [area3, ghostStandard] = leftArea(standard, g);
    auto [area4, ghostBest] = leftArea(best, g);
    std::printf(
        "  area the shadow left in the last %2d frames: %5lld px, wrong there: standard %lld, "
        "pixel-correct %lld, without rejection %lld, keep best %lld\n",
        g, area, ghostStandard, ghost, ghostNoReject, ghostBest);
    ASSERT_GT(area, 40);  // the shadow really moved
    (void)area2, (void)area3, (void)area4;
    // No lasting ghost: what the shadow left 16 frames (0.53 s) ago is lit again but for at most
    // 5% of the area, and the rejection rule does better than plain exponential smoothing there.
    // Within the last ~8 frames a trailing band remains (measured and printed above; a known
    // limitation, see techniques/accumulation/README.md).
    if (g >= 16) {
      EXPECT_LE(ghost, ghostStandard + area / 20) << "gap " << g;
      EXPECT_LT(ghost, ghostNoReject) << "gap " << g;
      EXPECT_LE(ghostBest, ghostStandard + area / 20) << "gap " << g;
    }
  }
  // Overall: the lagging band of the moving shadow stays below 1% of the image (measured 0.52%
  // with rejection, 0.98% without), and rejection reduces it.
  EXPECT_LT(pcCmp.metrics.wrongPixelPct, 1.0);
  EXPECT_LT(pcCmp.metrics.wrongPixelPct, nrCmp.metrics.wrongPixelPct);
  EXPECT_LT(bestCmp.metrics.wrongPixelPct, 1.0);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// Debug views are passes of their own and cost nothing unless shown.
TEST(PixelCorrect, DebugViewsRunOnlyWhenShown) {
  GlHarness h;
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  const int w = 160, hgt = 90;
  Viewport pc(makeTechnique("pixel-correct", {"shadowmap.size=256"}));
  FrameInput in = frameInput(scene.cameras.front(), w, hgt);
  h.renderer.render(in, {&pc});
  EXPECT_TRUE(hasPass(h.renderer, "pixel-correct[0]"));
  for (const char* v : {"confidence", "history", "disocclusion"})
    EXPECT_FALSE(hasPass(h.renderer, std::string("view.") + v + "[0]"));
  pc.shownViews = {"history"};
  h.renderer.render(in, {&pc});
  EXPECT_TRUE(hasPass(h.renderer, "view.history[0]"));
  EXPECT_FALSE(hasPass(h.renderer, "view.confidence[0]"));
  pc.shownViews = {"confidence", "history", "disocclusion"};
  h.renderer.render(in, {&pc});
  for (const char* v : {"confidence", "history", "disocclusion"}) {
    ASSERT_TRUE(hasPass(h.renderer, std::string("view.") + v + "[0]")) << v;
    auto px = pc.viewTexture(v)->readRgba8();
    long long lit = 0;
    for (size_t i = 0; i < px.size(); i += 4) lit += px[i] + px[i + 1] + px[i + 2] > 20;
    EXPECT_GT(lit, w * hgt / 4) << v;
  }
  EXPECT_TRUE(h.shaders.errors().empty());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// The G-buffer draws each pixel's previous-frame position only for a pass that reads it (the
// views); then a still camera finds its history at every covered pixel (grey in the
// disocclusion view; a motion target left unwritten would read as off-screen, blue).
TEST(PixelCorrect, MotionIsDrawnForTheViewsThatReadIt) {
  GlHarness h;
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  Viewport plain(makeTechnique("alias-free-pixel-correct", {}));
  Viewport viewed(makeTechnique("alias-free-pixel-correct", {}));
  viewed.shownViews = {"disocclusion"};
  FrameInput in = frameInput(scene.cameras.front(), 96, 54);
  for (int f = 0; f < 3; ++f) h.renderer.render(in, {&plain});
  for (int f = 0; f < 3; ++f) h.renderer.render(in, {&viewed});
  EXPECT_EQ(plain.visibilityTexture()->readFloats(2), viewed.visibilityTexture()->readFloats(2));
  auto px = viewed.viewTexture("disocclusion")->readRgba8();
  int covered = 0, historyUsed = 0;
  for (size_t i = 0; i < px.size(); i += 4) {
    if (px[i] + px[i + 1] + px[i + 2] == 0) continue;  // no geometry
    ++covered;
    historyUsed += px[i] == px[i + 2] && std::abs(px[i] - 89) <= 2;  // grey 0.35
  }
  ASSERT_GT(covered, 96 * 54 / 2);
  EXPECT_GT(historyUsed, covered * 95 / 100) << historyUsed << " of " << covered;
  EXPECT_TRUE(h.shaders.errors().empty());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

namespace fs = std::filesystem;
using test::lineOf;
using test::rewriteFile;

// Hot reload of the update shader: a broken edit keeps the last good program running and names
// pixel_correct.frag:LINE; the fix rebuilds it.
TEST(PixelCorrect, HotReloadOfTheUpdateShader) {
  fs::path dir = test::copyShaders("pixel_correct_shaders");
  GlHarness h(dir.string());
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  const int w = 96, hgt = 54;
  Viewport pc(makeTechnique("pixel-correct", {"shadowmap.size=256"}));
  FrameInput in = frameInput(scene.cameras.front(), w, hgt);
  for (int f = 0; f < 3; ++f) h.renderer.render(in, {&pc});
  ASSERT_TRUE(h.shaders.errors().empty());
  auto good = pc.visibilityTexture()->readFloats(2);

  const fs::path file = dir / "accumulation/pixel_correct.frag";
  rewriteFile(file, "float s = f;", "float s = f +* ;");
  h.shaders.reloadChanged();
  auto errors = h.shaders.errors();
  ASSERT_EQ(errors.size(), 1u);
  const int bad = lineOf(file, "+* ;");
  EXPECT_NE(errors[0].find("pixel_correct.frag:" + std::to_string(bad)), std::string::npos) << errors[0];
  h.renderer.render(in, {&pc});
  ASSERT_TRUE(hasPass(h.renderer, "pixel-correct[0]"));
  auto still = pc.visibilityTexture()->readFloats(2);
  double diff = 0;
  for (size_t i = 0; i < still.size(); i += 2) diff += std::abs(still[i] - good[i]);
  EXPECT_LT(diff / (w * hgt), 0.02);  // the last good program still accumulates (same view)
  EXPECT_EQ(test::readFrame(h.renderer, pc, w, hgt).nonfinite(), 0);

  // Fixed: rebuilt, and a visible change (w forced to 1: s = f) takes effect.
  rewriteFile(file, "float s = f +* ;", "float s = f;");
  rewriteFile(file, "o_history = vec4(s,", "o_history = vec4(f,");
  EXPECT_GE(h.shaders.reloadChanged(), 1);
  EXPECT_TRUE(h.shaders.errors().empty());
  h.renderer.render(in, {&pc});
  auto acc = pc.visibilityTexture()->readFloats(2), raw = pc.rawVisibilityTexture()->readFloats(2);
  int differ = 0;
  for (size_t i = 0; i < acc.size(); i += 2) differ += acc[i] != raw[i];
  EXPECT_EQ(differ, 0);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace sl
