// Normal-offset and slope bias on perspective (spot) maps: they ask the layout for the texel
// size before the layout rejects points at or behind the light's plane, so that size must
// stay finite and sane there, and no visibility may become NaN.
#include "gl_test_util.h"
#include "technique.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace sl {

using test::GlHarness;

namespace {

// A spot light at (0,5,0) looking straight down; a wall beside it crosses the light's plane
// and a slab above it lies behind the light, both seen by the camera.
const char* kSpotScene = R"({
  "objects": [
    {"name": "ground", "shape": "plane", "size": [16, 16], "subdivisions": 8},
    {"name": "box", "shape": "box", "size": [1, 1, 1], "transform": {"translate": [0.5, 0.5, 0]}},
    {"name": "wall", "shape": "box", "size": [0.3, 6, 4], "transform": {"translate": [3, 5, 0]}},
    {"name": "slab", "shape": "box", "size": [3, 0.2, 3], "transform": {"translate": [0, 6.5, 0]}}
  ],
  "light": {"type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "fov_deg": 120},
  "cameras": [{"name": "c", "position": [9, 4, 8], "target": [0, 4, 0], "fov_deg": 70, "near": 0.1, "far": 60}]
})";

// Evaluates, on a 16x16 grid in each of the planes y = 4 (in front of the light), 5 (through
// it) and 6 (behind it), the layout's texel size and the normal-offset projection.
const char* kSpotBiasProbe = R"(#include "common/bias.glsl"
layout(location = 0) out vec4 o_probe;
void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  vec3 P = vec3(float(px.x % 16) - 7.5, 4.0 + float(px.y / 16), float(px.y % 16) - 7.5) * vec3(0.5, 1.0, 0.5);
  vec3 N = normalize(vec3(0.3, 1.0, 0.2));
  ShadowCoord sc = layoutShadowCoordIn(biasReceiverPosition(P, N, 0.5, 0), 0);
  o_probe = vec4(layoutTexelWorldSize(P, 0), sc.view < 0 ? vec3(0.0) : vec3(sc.uv, sc.depth));
}
)";

}  // namespace

TEST(SpotBias, TexelSizeIsFiniteAndSaneAtAndBehindTheLightPlane) {
  const std::string dir = test::copyShaders("spot_bias_probe");
  std::ofstream(std::filesystem::path(dir) / "probe_bias.frag") << kSpotBiasProbe;
  GlHarness h(dir);
  Scene scene = loadScene(test::writeTempFile("spot_probe.json", kSpotScene), defaultAssetsDir());
  Technique t = makeTechnique("standard", {"shadowmap.size=256", "bias.mode=normal-offset"});
  LayoutInput li{&scene, 0.0, cameraView(scene.cameras[0]), cameraProjection(scene.cameras[0], 1.0f), &t.params, {}};
  LightSpace ls = t.layout->compute(li);
  ASSERT_TRUE(ls.primary().perspective);
  // What Renderer::techniquePrelude writes for this technique and scene.
  const std::string prelude =
      "#define SL_BIAS_MODE_IS_NORMAL_OFFSET\n#define SL_SPOT_LIGHT\n#define SL_PERSPECTIVE_MAP\n#define SL_LIGHT_VIEWS 1\n#include "
      "\"" +
      t.layout->glslModule() + "\"\n#ifdef SL_FRAGMENT\n#include \"" + t.representation->glslModule() + "\"\n#endif\n";
  Program& p = h.shaders.get(
      {"probe", {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "probe_bias.frag"}}, prelude});
  ASSERT_TRUE(p.valid()) << p.error();
  Texture2D target(GL_RGBA32F, 16, 48, "probe");
  Framebuffer fbo("probe");
  fbo.attach({&target}, nullptr);
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  fbo.bind();
  p.use();
  setTechniqueUniforms(p, t, ls, scene.light);
  LightViewsBuffer views;
  views.upload(ls);
  views.bind();
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vao);
  std::vector<float> v = target.readFloats(4);
  float largest = 0.0f;
  long long nonfinite = 0;
  for (size_t i = 0; i < v.size(); i += 4) {
    for (int c = 0; c < 4; ++c) nonfinite += std::isfinite(v[i + c]) ? 0 : 1;
    EXPECT_GT(v[i], 0.0f) << "texel size at probe " << i / 4;
    largest = std::max(largest, v[i]);
  }
  EXPECT_EQ(nonfinite, 0);
  // A 256² map with a 120° cone: a texel is ~0.014 units wide at unit distance, so anything
  // near a world unit is the division by w = 0 at the light's plane leaking out.
  EXPECT_LT(largest, 0.1f) << "largest texel size among the probes";
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(SpotBias, NoNanVisibilityWithGeometryBesideAndBehindTheSpotLight) {
  GlHarness h;
  Scene scene = loadScene(test::writeTempFile("spot_beside.json", kSpotScene), defaultAssetsDir());
  h.renderer.setScene(scene);
  for (const std::string preset : {"standard", "pcf", "lispsm", "pixel-correct"}) {
    for (const std::string mode : {"normal-offset", "slope"}) {
      Viewport vp(makeTechnique(preset, {"shadowmap.size=256", "bias.mode=" + mode}));
      FrameInput in;
      in.camera = scene.cameras[0];
      in.width = 96;
      in.height = 64;
      h.renderer.render(in, {&vp});
      test::Frame f = test::readFrame(h.renderer, vp, in.width, in.height);
      EXPECT_EQ(f.nonfinite(), 0) << preset << " " << mode;
      long long badConfidence = 0;
      for (size_t i = 1; i < f.visibility.size(); i += 2) badConfidence += std::isfinite(f.visibility[i]) ? 0 : 1;
      EXPECT_EQ(badConfidence, 0) << preset << " " << mode;
    }
  }
  EXPECT_TRUE(h.shaders.errors().empty());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace sl
