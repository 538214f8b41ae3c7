// image_wrong_pct on llvmpipe: a technique's colour against the deferred shade pass with the
// reference visibility substituted (Renderer::shadeWithVisibility). The same visibility gives
// the same image; a visibility error under grazing light is wrong in visibility but not in the
// image, which is where the two figures part.
#include "bench/reference_cache.h"
#include "gl_test_util.h"
#include "technique.h"

#include <cmath>

namespace sl {

using test::GlHarness;

namespace {

constexpr int kMetricW = 32, kMetricH = 20;  // 640 pixels, most of them ground

// A ground plane under a directional light `elevationDeg` above the horizon, plus a box whose
// shadow gives the techniques something to get wrong.
Scene groundScene(float elevationDeg) {
  const float e = glm::radians(elevationDeg);
  const std::string dir = std::to_string(-std::cos(e) * 0.8f) + ", " + std::to_string(-std::sin(e)) + ", " +
                          std::to_string(-std::cos(e) * 0.6f);
  const std::string text = R"({
  "objects": [
    {"name": "ground", "shape": "plane", "size": [20, 20], "subdivisions": 4},
    {"name": "box", "shape": "box", "size": [1, 1, 1], "transform": {"translate": [0, 0.5, 0]}}
  ],
  "light": {"type": "directional", "direction": [)" +
                           dir + R"(]},
  "cameras": [{"name": "c", "position": [-3.5, 4, 2.5], "target": [-0.6, 0, -0.4], "fov_deg": 60, "near": 0.1, "far": 60}]
})";
  return loadScene(test::writeTempFile("ground_" + std::to_string(int(elevationDeg * 10)) + ".json", text),
                   defaultAssetsDir());
}

FrameInput frameOf(const Scene& scene) {
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = kMetricW;
  in.height = kMetricH;
  return in;
}

// Ground pixels (y = 0) of the last frame's G-buffer.
std::vector<uint8_t> groundMask(const Renderer& r) {
  const std::vector<float> p = r.gPosition().readFloats(4);
  std::vector<uint8_t> ground(p.size() / 4, 0);
  for (size_t i = 0; i < ground.size(); ++i) ground[i] = p[4 * i + 3] > 0.5f && std::abs(p[4 * i + 1]) < 1e-3f;
  return ground;
}

// `vis` with every other ground pixel inverted: the same visibility error under any light.
std::vector<float> invertHalfTheGround(std::vector<float> vis, const std::vector<uint8_t>& ground, long long& flipped) {
  flipped = 0;
  for (size_t i = 0; i < vis.size(); ++i)
    if (ground[i] && i % 2 == 0) {
      vis[i] = 1.0f - vis[i];
      ++flipped;
    }
  return vis;
}

}  // namespace

TEST(ImageMetric, SameVisibilityGivesTheSameImage) {
  GlHarness h;
  Scene scene = groundScene(40.0f);
  h.renderer.setScene(scene);
  const FrameInput in = frameOf(scene);
  // Forward shading (standard, pcf) and the pixel-correct scene pass shade in their own passes;
  // the deferred shade pass must give the same colour for the same visibility.
  for (const std::string preset : {"standard", "pcf", "pixel-correct"}) {
    Viewport vp(makeTechnique(preset, {"shadowmap.size=512"}));
    h.renderer.keepGBuffer = true;
    h.renderer.render(in, {&vp});
    const std::vector<uint8_t> valid = groundMask(h.renderer);
    // Later frames without the G-buffer: shadeWithVisibility draws it itself.
    h.renderer.keepGBuffer = false;
    for (int f = 0; f < 3; ++f) h.renderer.render(in, {&vp});
    ASSERT_FALSE(h.renderer.hasFreshGBuffer());
    const std::vector<float> vis = viewportVisibility(vp);
    const ImageErrorMetrics m = viewportImageError(h.renderer, in, vp, vis, valid);
    EXPECT_GT(m.validPixels, 300) << preset;
    EXPECT_DOUBLE_EQ(m.imageWrongPct, 0.0) << preset;
    // And it did shade: a different visibility is a different image.
    long long flipped = 0;
    const std::vector<float> other = invertHalfTheGround(vis, valid, flipped);
    EXPECT_GT(viewportImageError(h.renderer, in, vp, other, valid).imageWrongPct, 30.0) << preset;
  }
  EXPECT_TRUE(h.shaders.errors().empty());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(ImageMetric, GrazingLightHidesVisibilityErrorsFromTheImage) {
  GlHarness h;
  ReferenceSettings settings;
  settings.useCache = false;
  struct Result {
    ErrorMetrics visibility;
    ImageErrorMetrics image;
    long long flipped = 0;
  };
  // The same kind of visibility error (every other ground pixel inverted against the truth)
  // under a light 60 degrees and 1 degree above the ground (N.L = 0.87 and 0.017).
  auto measure = [&](float elevationDeg) {
    Scene scene = groundScene(elevationDeg);
    h.renderer.setScene(scene);
    const FrameInput in = frameOf(scene);
    Viewport vp(makeTechnique("standard", {"shadowmap.size=2048"}));
    h.renderer.render(in, {&vp});
    const ReferenceImage truth = ReferenceCache(scene, settings).forLastFrame(h.renderer, in);
    const std::vector<uint8_t> ground = groundMask(h.renderer);
    Result r;
    std::vector<float> wrongTruth = invertHalfTheGround(truth.visibility, ground, r.flipped);
    const std::vector<float> vis = viewportVisibility(vp);
    // Over the ground only: the box's sides face even the grazing light.
    r.visibility = compareVisibility(vis.data(), wrongTruth.data(), ground.data(), vis.size());
    r.image = viewportImageError(h.renderer, in, vp, wrongTruth, ground);
    return r;
  };
  const Result high = measure(60.0f), grazing = measure(1.0f);
  for (const Result* r : {&high, &grazing}) {
    ASSERT_GT(r->flipped, 200);
    // Every inverted pixel is a visibility error (the technique agrees with the truth elsewhere
    // but for a few edge pixels).
    EXPECT_GE(r->visibility.wrongPixelPct, 100.0 * double(r->flipped) / double(r->visibility.validPixels) - 2.0);
  }
  // Lit at N.L = 0.87 the error shows in the colour; at N.L = 0.017 the light adds less than
  // 30/255 to any colour, so not one of those pixels is image-wrong.
  EXPECT_GT(high.image.imageWrongPct, 0.9 * high.visibility.wrongPixelPct - 2.0);
  EXPECT_GT(grazing.visibility.wrongPixelPct, 30.0);
  EXPECT_DOUBLE_EQ(grazing.image.imageWrongPct, 0.0);
  std::printf("60 deg: wrong %.1f %%, image-wrong %.1f %%; 1 deg: wrong %.1f %%, image-wrong %.1f %%\n",
              high.visibility.wrongPixelPct, high.image.imageWrongPct, grazing.visibility.wrongPixelPct,
              grazing.image.imageWrongPct);
  EXPECT_TRUE(h.shaders.errors().empty());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(ImageMetric, GrazingAcneIsWrongVisibilityButNotAWrongImage) {
  GlHarness h;
  // A real technique error rather than a made-up one: without bias a grazing light makes the
  // ground shadow itself (acne) over much of the view, and the shading hides all of it.
  Scene scene = groundScene(1.0f);
  h.renderer.setScene(scene);
  const FrameInput in = frameOf(scene);
  Viewport vp(makeTechnique("standard", {"shadowmap.size=1024", "bias.mode=none"}));
  h.renderer.render(in, {&vp});
  ReferenceSettings settings;
  settings.useCache = false;
  const ReferenceImage truth = ReferenceCache(scene, settings).forLastFrame(h.renderer, in);
  // The ground only: the box's sides face even the grazing light.
  const std::vector<uint8_t> ground = groundMask(h.renderer);
  const std::vector<float> vis = viewportVisibility(vp);
  const ErrorMetrics m = compareVisibility(vis.data(), truth.visibility.data(), ground.data(), vis.size());
  const ImageErrorMetrics img = viewportImageError(h.renderer, in, vp, truth.visibility, ground);
  EXPECT_EQ(img.validPixels, m.validPixels);
  EXPECT_GT(m.falseShadowPct, 5.0);
  EXPECT_DOUBLE_EQ(img.imageWrongPct, 0.0);
  std::printf("acne at 1 deg: wrong %.1f %% (false shadow %.1f %%), image-wrong %.1f %%\n", m.wrongPixelPct,
              m.falseShadowPct, img.imageWrongPct);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace sl
