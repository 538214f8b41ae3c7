// Pre-filtered representations across world depth ranges and at a depth discontinuity:
// the same scene built at 10^-3, 1 and 10^4 times its size must be shadowed equally well in
// 16- and 32-bit storage (the map stores light depth normalized over the light's range, so
// nothing may depend on world units), and a floor of tiles with a gap between them (the depth
// discontinuity a reported ESM leak came from) must keep its umbra dark and its lit part lit.
#include "metrics/metrics.h"
#include "tests/gl_test_util.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>

namespace sl {
namespace {

const std::vector<std::string> kPrefiltered = {"vsm",  "esm", "evsm2", "evsm4",      "gaussian",
                                               "ewgf", "msm", "msm16", "convolution"};

// The scene as if built `s` times larger: every instance, camera and the light's position.
Scene scaled(Scene scene, float s) {
  const glm::mat4 m = glm::scale(glm::mat4(1.0f), glm::vec3(s));
  for (auto& inst : scene.instances) inst.transform = m * inst.transform;
  for (auto& c : scene.cameras) {
    c.position *= s;
    c.target *= s;
    c.nearPlane *= s;
    c.farPlane *= s;
  }
  scene.light.position *= s;
  if (scene.light.type == Light::Type::Spot) scene.light.radius *= s;
  return scene;
}

struct Judged {
  double wrongPct = 0;
  long long umbraLit = 0, lightDark = 0, outside = 0;
};

// Renders `preset` and compares with the ray-traced reference; "umbra" and "light" are the
// pixels whose reference value and whole 5x5 neighbourhood are 0 (resp. 1): no filter may
// reach across them, so a technique that lights an umbra pixel leaks.
Judged judge(test::GlHarness& h, const Scene& scene, const std::string& preset, const std::vector<std::string>& sets,
             int w, int hgt) {
  const test::Frame f = test::renderOnce(h, scene, preset, sets, w, hgt);
  ReferenceTracer tracer(scene, 0.0);
  const std::vector<float> ref = tracer.visibility(f.gbuffer(), ReferenceOptions{});
  const std::vector<float> vis = f.visibilityChannel();
  const std::vector<uint8_t> valid = f.covered();
  Judged j;
  for (float v : vis)
    if (!(v >= 0.0f && v <= 1.0f)) ++j.outside;  // NaN counts
  j.wrongPct = compareVisibility(vis.data(), ref.data(), valid.data(), vis.size()).wrongPixelPct;
  for (int y = 2; y < hgt - 2; ++y)
    for (int x = 2; x < w - 2; ++x) {
      bool allDark = true, allLit = true;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          const size_t k = static_cast<size_t>(y + dy) * w + (x + dx);
          allDark = allDark && valid[k] && ref[k] == 0.0f;
          allLit = allLit && valid[k] && ref[k] == 1.0f;
        }
      const float v = vis[static_cast<size_t>(y) * w + x];
      if (allDark && v > 0.5f) ++j.umbraLit;
      if (allLit && v < 0.5f) ++j.lightDark;
    }
  return j;
}

TEST(PrefilteredDepthRange, SameShadowsFromAMillimetreToTenKilometres) {
  test::GlHarness h;
  const Scene base = loadScene("basic", defaultAssetsDir());
  for (const std::string& preset : kPrefiltered)
    for (const std::string format : {"float16", "float32"}) {
      const std::vector<std::string> sets = {"shadowmap.size=256", "filter.format=" + format};
      const Judged unit = judge(h, base, preset, sets, 96, 54);
      for (float s : {1e-3f, 1e4f}) {
        const Judged j = judge(h, scaled(base, s), preset, sets, 96, 54);
        EXPECT_EQ(j.outside, 0) << preset << " " << format << " at scale " << s;
        // A few pixels may flip where the G-buffer's float positions round differently; more in
        // float16, where a receiver lies within the storage's rounding of its own occluder.
        EXPECT_NEAR(j.wrongPct, unit.wrongPct, format == "float16" ? 1.5 : 0.5)
            << preset << " " << format << " at scale " << s;
        std::printf("%-12s %s scale %-6g wrong %.2f %% (scale 1: %.2f %%)\n", preset.c_str(), format.c_str(), s,
                    j.wrongPct, unit.wrongPct);
      }
    }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// Floor tiles 2 cm apart over a lower floor, half under a roof: the gap is a depth
// discontinuity inside every filter kernel that covers it.
const char* kTileGapScene = R"({
  "name": "tile-gap",
  "objects": [
    {"name": "lower", "shape": "plane", "size": [12, 12], "color": [0.5, 0.5, 0.5],
     "transform": {"translate": [0, -0.3, 0]}},
    {"name": "tile-a", "shape": "box", "size": [2.99, 0.1, 6], "color": [0.8, 0.8, 0.8],
     "transform": {"translate": [-1.505, -0.05, 0]}},
    {"name": "tile-b", "shape": "box", "size": [2.99, 0.1, 6], "color": [0.8, 0.8, 0.8],
     "transform": {"translate": [1.505, -0.05, 0]}},
    {"name": "roof", "shape": "box", "size": [8, 0.1, 2.5], "color": [0.7, 0.3, 0.3],
     "transform": {"translate": [0, 2.0, -1.2]}}
  ],
  "light": {"type": "directional", "direction": [0.15, -1, 0.1], "radius": 0},
  "cameras": [{"name": "default", "position": [0.3, 4.5, 4.5], "target": [0, 0, -0.5],
               "fov_deg": 55, "near": 0.1, "far": 50}]
})";

TEST(PrefilteredDepthRange, TileGapKeepsTheUmbraDarkAndTheLightLit) {
  test::GlHarness h;
  const Scene scene = loadScene(test::writeTempFile("tile-gap.json", kTileGapScene), defaultAssetsDir());
  for (const std::string& preset : kPrefiltered)
    for (const std::string format : {"float16", "float32"}) {
      // Four moments rounded to float16 without the paper's quantization transform are the case
      // msm16 exists for (checked below), not a configuration that must hold.
      if (preset == "msm" && format == "float16") continue;
      const Judged j = judge(h, scene, preset, {"shadowmap.size=512", "filter.format=" + format}, 160, 90);
      EXPECT_EQ(j.outside, 0) << preset << " " << format;
      EXPECT_EQ(j.umbraLit, 0) << preset << " " << format << ": umbra pixels lit (a leak through the gap)";
      EXPECT_EQ(j.lightDark, 0) << preset << " " << format << ": lit pixels shadowed";
    }
  const Judged plain16 = judge(h, scene, "msm", {"shadowmap.size=512", "filter.format=float16"}, 160, 90);
  const Judged msm16 = judge(h, scene, "msm16", {"shadowmap.size=512"}, 160, 90);
  EXPECT_GT(plain16.umbraLit + plain16.lightDark, 0) << "MSM in plain float16 no longer fails: msm16's reason is gone";
  EXPECT_LT(msm16.wrongPct, plain16.wrongPct);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace
}  // namespace sl
