// pixel-correct-soft: the light sample moves over the disk (Halton, uniform in area), the layouts
// follow it, and at rest the history converges to the area light's visibility: after 30 still
// frames on `contact` well below its first frame's error and below pcss.
#include "accumulation/pixel_correct.h"
#include "part/light_frame.h"
#include "metrics/metrics.h"
#include "reference/reference.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <glm/gtc/matrix_transform.hpp>

namespace sl {
namespace {

using test::Frame;
using test::GlHarness;

TEST(PixelCorrectSoft, LightSamplesCoverTheDiskUniformly) {
  Technique t = makeTechnique("pixel-correct-soft");
  const int n = 256;
  int inner = 0, quadrant[4] = {0, 0, 0, 0};
  glm::vec2 mean(0.0f);
  for (int i = 0; i < n; ++i) {
    const glm::vec2 s = pixelCorrectJitter(t.params, i).lightSample;
    ASSERT_LE(glm::length(s), 1.0f + 1e-5f) << i;
    inner += glm::length(s) < std::sqrt(0.5f) ? 1 : 0;  // half the disk's area
    quadrant[(s.x > 0 ? 1 : 0) + (s.y > 0 ? 2 : 0)]++;
    mean += s / float(n);
  }
  EXPECT_NEAR(inner, n / 2, n / 16);
  for (int q : quadrant) EXPECT_NEAR(q, n / 4, n / 16);
  EXPECT_LT(glm::length(mean), 0.05f);
  // Off by default in plain pixel-correct: its goldens keep the point light.
  EXPECT_EQ(pixelCorrectJitter(makeTechnique("pixel-correct").params, 3).lightSample, glm::vec2(0.0f));
}

TEST(PixelCorrectSoft, SampledLightStaysOnTheDisk) {
  Light sun;
  sun.direction = glm::normalize(glm::vec3(0.6f, -0.55f, 0.2f));
  sun.radius = 0.04f;
  const Light edge = sampledLight(sun, {1.0f, 0.0f});
  // Tilted by the angular radius: tan(angle) = radius.
  const float cosAngle = glm::dot(edge.direction, sun.direction);
  EXPECT_NEAR(std::sqrt(1.0f - cosAngle * cosAngle) / cosAngle, 0.04f, 1e-4f);
  Light spot = sun;
  spot.type = Light::Type::Spot;
  spot.radius = 0.5f;
  const Light moved = sampledLight(spot, {0.0f, -1.0f});
  EXPECT_NEAR(glm::length(moved.position - spot.position), 0.5f, 1e-5f);
  EXPECT_NEAR(glm::dot(moved.position - spot.position, spot.direction), 0.0f, 1e-5f);  // in the disk's plane
  sun.radius = 0.0f;
  EXPECT_EQ(sampledLight(sun, {1.0f, 0.0f}).direction, sun.direction);
}

TEST(PixelCorrectSoft, ConvergesBelowPcssOnContact) {
  GlHarness h;
  const Scene scene = loadScene("contact", defaultAssetsDir());
  h.renderer.setScene(scene);
  const int w = 160, hgt = 90;
  ReferenceTracer tracer(scene, 0.0);
  auto rmse = [&](const Frame& f) { return test::visibilityError(tracer, f).rmse; };
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = w;
  in.height = hgt;
  Viewport pcss(makeTechnique("pcss"));
  h.renderer.render(in, {&pcss});
  const double pcssRmse = rmse(test::readFrame(h.renderer, pcss, w, hgt));

  Viewport vp(makeTechnique("pixel-correct-soft"));
  std::vector<double> err;
  for (int frame = 0; frame < 30; ++frame) {
    h.renderer.render(in, {&vp});
    if (frame == 0 || frame == 29) err.push_back(rmse(test::readFrame(h.renderer, vp, w, hgt)));
  }
  EXPECT_TRUE(h.shaders.errors().empty());
  EXPECT_LT(err[1], 0.5 * err[0]) << "first " << err[0] << " after 30 " << err[1];
  EXPECT_LT(err[1], pcssRmse) << "pixel-correct-soft " << err[1] << " pcss " << pcssRmse;
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace
}  // namespace sl
