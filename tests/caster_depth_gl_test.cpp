// passes/caster_depth.glsl: where a layout's stored depth is affine in the world position
// (light-view linear depth), the shadow passes compute it per vertex and interpolate it, instead
// of interpolating the position and computing it per fragment. Perspective-correct interpolation
// reproduces an affine function exactly, so the maps must hold the same depths up to rounding:
// compared here against the same shaders with the per-vertex path switched off, for a layout of
// four warped views, a spot light's perspective map and a point light's cube faces. Measured
// apart: at most 4.6e-6 (face-partitioned), 6.3e-7 (spot), 1.3e-5 (cube, whose near plane is
// close to the light); the bound is a tenth of the default constant bias (5e-4).
#include "tests/gl_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sl {
namespace {

std::vector<float> shadowDepth(const std::string& shaderDir, const std::string& sceneName, const std::string& preset) {
  test::GlHarness h(shaderDir);
  const Scene scene = loadScene(sceneName, defaultAssetsDir());
  h.renderer.setScene(scene);
  return test::renderShadowDepth(h, scene, preset, {"shadowmap.size=512"});
}

}  // namespace

TEST(CasterDepthGl, PerVertexDepthStoresWhatEachFragmentComputed) {
  const std::string perFragment = test::copyShaders("caster-depth-per-fragment");
  test::rewriteFile(perFragment + "/passes/caster_depth.glsl", "#define SL_CASTER_DEPTH_VARYING\n", "");
  const std::pair<const char*, const char*> cases[] = {
      {"basic", "face-partitioned"}, {"spotlight", "lispsm"}, {"street-lamps", "cube"}};
  for (const auto& [scene, preset] : cases) {
    const std::vector<float> vertex = shadowDepth(defaultShaderDir(), scene, preset);
    const std::vector<float> fragment = shadowDepth(perFragment, scene, preset);
    ASSERT_EQ(vertex.size(), fragment.size()) << scene << " " << preset;
    size_t written = 0, apart = 0;
    float most = 0.0f;
    for (size_t i = 0; i < vertex.size(); ++i) {
      written += fragment[i] < 1.0f;
      const float d = std::abs(vertex[i] - fragment[i]);
      apart += !(d <= 5e-5f);  // NaN counts
      most = std::max(most, d);
    }
    std::printf("%s %s: %zu of %zu texels written, largest difference %g\n", scene, preset, written, vertex.size(),
                static_cast<double>(most));
    EXPECT_EQ(apart, 0u) << scene << " " << preset << ": largest difference " << most;
    EXPECT_GT(written, vertex.size() / 16) << scene << " " << preset;  // casters drawn: the comparison means something
  }
}

}  // namespace sl
