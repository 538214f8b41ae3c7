// Sample-distribution fitting on llvmpipe: the GPU reduction finds the visible pixels' depth
// range and light-space box (checked against the G-buffer read back), its result arrives after
// fit.sdsm_latency frames, and the fitted maps stay finite.
#include "layouts/cascade_fit.h"
#include "part/light_frame.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <algorithm>

namespace sl {
namespace {

FrameInput frame(const Camera& cam, bool cut) {
  FrameInput in;
  in.camera = cam;
  in.width = 160;
  in.height = 90;
  in.cut = cut;
  return in;
}

TEST(SdsmGl, SplitsFollowTheVisibleDepthRangeAfterTheLatency) {
  test::GlHarness h;
  Scene scene = loadScene("terrain", defaultAssetsDir());
  h.renderer.setScene(scene);
  const Camera& cam = scene.cameras.front();
  for (int latency = 0; latency <= 3; ++latency) {
    Viewport vp(makeTechnique("sdsm", {"shadowmap.size=256", "fit.sdsm_latency=" + std::to_string(latency)}));
    Viewport plain(makeTechnique("cascaded", {"shadowmap.size=256"}));
    for (int f = 0; f <= latency; ++f) {
      h.renderer.render(frame(cam, f == 0), {&vp, &plain});
      const float first = vp.lightSpace.views.front().splitNear;
      // Until the first reduction arrives the splits are the plain cascades'.
      if (f < latency)
        EXPECT_FLOAT_EQ(first, plain.lightSpace.views.front().splitNear) << "latency " << latency << " frame " << f;
      else
        EXPECT_GT(first, plain.lightSpace.views.front().splitNear * 5.0f) << "latency " << latency;
      EXPECT_EQ(test::readFrame(h.renderer, vp, 160, 90).nonfinite(), 0);
    }
    // The visible depth range, from the G-buffer of the last frame (the camera stood still).
    const test::Frame g = test::readFrame(h.renderer, vp, 160, 90);
    const glm::mat4 view = cameraView(cam);
    float lo = 1e30f, hi = -1e30f;
    for (size_t i = 0; i < g.position.size(); i += 4) {
      if (g.position[i + 3] < 0.5f) continue;
      const float d = -(view * glm::vec4(g.position[i], g.position[i + 1], g.position[i + 2], 1.0f)).z;
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    EXPECT_NEAR(vp.lightSpace.views.front().splitNear, lo * 0.99f, 1e-3f * lo) << "latency " << latency;
    // And every split border is the practical scheme's over that range (1 % margins).
    const auto splits = cascadeSplits(4, SplitScheme::Practical, 0.95f, lo * 0.99f, std::min(cam.farPlane, hi * 1.01f));
    for (size_t i = 0; i < vp.lightSpace.views.size(); ++i)
      EXPECT_NEAR(vp.lightSpace.views[i].splitNear, splits[i], 2e-3f * splits[i]) << "latency " << latency;
  }
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(SdsmGl, FocusedFitsTheVisiblePixelsLightSpaceBox) {
  test::GlHarness h;
  Scene scene = loadScene("columns", defaultAssetsDir());
  h.renderer.setScene(scene);
  const Camera& cam = scene.cameras.front();
  Viewport vp(makeTechnique("standard", {"shadowmap.size=512", "fit.sdsm=on", "fit.sdsm_latency=0"}));
  Viewport plain(makeTechnique("standard", {"shadowmap.size=512"}));
  h.renderer.render(frame(cam, true), {&vp, &plain});
  const test::Frame g = test::readFrame(h.renderer, vp, 160, 90);
  EXPECT_EQ(g.nonfinite(), 0);
  // Every visible pixel inside the window, and the window no larger than the plain focused one.
  const LightView& v = vp.lightSpace.primary();
  int covered = 0;
  for (size_t i = 0; i < g.position.size(); i += 4) {
    if (g.position[i + 3] < 0.5f) continue;
    const glm::vec4 c = v.viewProj * glm::vec4(g.position[i], g.position[i + 1], g.position[i + 2], 1.0f);
    EXPECT_LE(std::abs(c.x / c.w), 1.0f);
    EXPECT_LE(std::abs(c.y / c.w), 1.0f);
    ++covered;
  }
  EXPECT_GT(covered, 1000);
  EXPECT_LT(v.texelWorldSize, plain.lightSpace.primary().texelWorldSize);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// With a latency the reduction reads the shaded frame's depth after the shading, so a forward-
// shaded frame draws no G-buffer for it; without one it must run before the shadow pass, over
// the G-buffer. Both keep the bounds (the test above checks their values at every latency).
TEST(SdsmGl, ALaterFramesFitReadsTheShadedDepthNotAGBuffer) {
  test::GlHarness h;
  Scene scene = loadScene("terrain", defaultAssetsDir());
  h.renderer.setScene(scene);
  h.renderer.keepGBuffer = false;  // as the window and the bench draw: nothing reads it back
  auto passes = [&] {
    std::vector<std::string> n;
    for (const auto& p : h.renderer.stats().passes) n.push_back(p.name);
    return n;
  };
  auto has = [](const std::vector<std::string>& n, const std::string& name) {
    return std::find(n.begin(), n.end(), name) != n.end();
  };
  const Camera& cam = scene.cameras.front();
  Viewport later(makeTechnique("sdsm", {"shadowmap.size=256", "fit.sdsm_latency=1"}));
  Viewport plain(makeTechnique("cascaded", {"shadowmap.size=256"}));
  for (int f = 0; f < 2; ++f) h.renderer.render(frame(cam, f == 0), {&later});
  const std::vector<std::string> n = passes();
  EXPECT_FALSE(has(n, "gbuffer"));
  EXPECT_TRUE(has(n, "sdsm.reduce[0]"));
  EXPECT_LT(std::find(n.begin(), n.end(), "shade[0]"), std::find(n.begin(), n.end(), "sdsm.reduce[0]"));
  h.renderer.render(frame(cam, true), {&plain});
  EXPECT_GT(later.lightSpace.views.front().splitNear, plain.lightSpace.views.front().splitNear * 5.0f)
      << "the bounds of the first frame arrived in the second";
  Viewport now(makeTechnique("sdsm", {"shadowmap.size=256", "fit.sdsm_latency=0"}));
  h.renderer.render(frame(cam, true), {&now});
  EXPECT_TRUE(has(passes(), "gbuffer"));
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace
}  // namespace sl
