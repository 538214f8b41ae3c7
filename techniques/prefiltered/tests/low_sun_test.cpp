// Issue #23: pre-filtered visibility under a very low sun. A 200 x 200 ground with basic's box and
// sphere under a sun 0.5 and 0.05 degrees above the horizon (a lecture's sunset slider reaches
// both). The shaded image hides a wrong visibility there (N.L is nearly 0), the visibility does
// not: ewgf marked 85-91 % of the pixels falsely shadowed at 0.5 degrees (the Gaussian read the
// receiver's own plane spread over the filter box as occluders) and convolution 82 % at 0.05
// (the slope bias moved the receiver out of the Fourier series' period). Each preset must stay
// within the bar: at most max(5 %, 3x standard's) wrong pixels against the ray-traced
// reference, and finite.
#include "metrics/metrics.h"
#include "tests/gl_test_util.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>

namespace sl {
namespace {

struct LowSun {
  float elevationDeg;
  std::string preset;
};
void PrintTo(const LowSun& c, std::ostream* os) { *os << c.elevationDeg << " deg " << c.preset; }

Scene lowSunScene(float elevationDeg) {
  Scene scene = loadScene("basic", defaultAssetsDir());
  scene.instances[0].transform = scene.instances[0].transform * glm::scale(glm::mat4(1.0f), glm::vec3(10, 1, 10));
  const float e = glm::radians(elevationDeg);
  scene.light.direction = glm::normalize(glm::vec3(-0.8f * std::cos(e), -std::sin(e), 0.6f * std::cos(e)));
  return scene;
}

ErrorMetrics wrongAgainstTruth(test::GlHarness& h, const Scene& scene, const std::string& preset) {
  const test::Frame f = test::renderOnce(h, scene, preset, {}, 160, 90);
  ReferenceTracer tracer(scene, 0.0);
  const std::vector<float> ref = tracer.visibility(f.gbuffer(), ReferenceOptions{});
  const std::vector<float> vis = f.visibilityChannel();
  const std::vector<uint8_t> valid = f.covered();
  return compareVisibility(vis.data(), ref.data(), valid.data(), vis.size());
}

// Where shared/scenes-real is (SHADOWLAB_SHARED, else beside the source tree).
std::string lowSunSharedDir() {
  const char* env = std::getenv("SHADOWLAB_SHARED");
  return env && *env ? env : std::string(SHADOWLAB_SOURCE_DIR) + "/../shared";
}

class PrefilteredLowSun : public ::testing::TestWithParam<LowSun> {};

TEST_P(PrefilteredLowSun, AtMostThreeTimesStandardsWrongPixels) {
  test::GlHarness h;
  const Scene scene = lowSunScene(GetParam().elevationDeg);
  const ErrorMetrics standard = wrongAgainstTruth(h, scene, "standard");
  const ErrorMetrics m = wrongAgainstTruth(h, scene, GetParam().preset);
  EXPECT_EQ(m.nonfinite, 0);
  EXPECT_LE(m.wrongPixelPct, std::max(5.0, 3.0 * standard.wrongPixelPct))
      << "false shadow " << m.falseShadowPct << " %, false light " << m.falseLightPct << " %; standard "
      << standard.wrongPixelPct << " %";
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// Sponza under a sun 3 degrees up: nearly everything is in shadow, and layered VSM read a bright
// band past each layer boundary (5.9 % false light, standard 0.04 %): occluders of earlier layers
// sit at warped 0, within the floor of a receiver just past its layer's start. msm16 leaked 6.4 %
// there with the paper's moment bias 6e-5 (16-bit moments against a long light depth range).
TEST(PrefilteredLowSunReal, MomentMapsUnderAThreeDegreeSunInSponza) {
  if (!std::ifstream(lowSunSharedDir() + "/scenes-real/sponza/Sponza.gltf"))
    GTEST_SKIP() << "shared/scenes-real not found under " << lowSunSharedDir() << ": Sponza is not compared";
  test::GlHarness h;
  Scene scene = loadScene("sponza", defaultAssetsDir());
  const float e = glm::radians(3.0f);
  scene.light.direction = glm::normalize(glm::vec3(0.95f * std::cos(e), -std::sin(e), 0.31f * std::cos(e)));
  const ErrorMetrics standard = wrongAgainstTruth(h, scene, "standard");
  for (const std::string preset : {"vsm", "lvsm", "msm", "msm16"}) {
    const ErrorMetrics m = wrongAgainstTruth(h, scene, preset);
    EXPECT_EQ(m.nonfinite, 0) << preset;
    EXPECT_LE(m.wrongPixelPct, std::max(5.0, 3.0 * standard.wrongPixelPct))
        << preset << ": false light " << m.falseLightPct << " %; standard " << standard.wrongPixelPct << " %";
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

std::vector<LowSun> lowSunCases() {
  std::vector<LowSun> cases;
  for (float e : {0.5f, 0.05f})
    for (const char* p : {"vsm", "esm", "evsm2", "evsm4", "gaussian", "ewgf", "msm", "msm16", "lvsm", "convolution",
                          "convolution-soft", "vssm"})
      cases.push_back({e, p});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Sun, PrefilteredLowSun, ::testing::ValuesIn(lowSunCases()), [](const auto& info) {
  std::string name = (info.param.elevationDeg > 0.1f ? "deg0_5_" : "deg0_05_") + info.param.preset;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

}  // namespace
}  // namespace sl
