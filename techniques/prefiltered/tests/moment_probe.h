// Test helper: runs a representation's real GLSL (representationMoments and
// representationFromMoments, from its module under shaders/representations/prefiltered/) on
// cases given per pixel, without a scene: each case is a kernel holding depth z1 over a
// `fraction` of its texels and z2 over the rest, filtered as the map's filter would (linear, or
// in log space for ESM; rounded to 16-bit floats when the format is float16), and a receiver
// depth. Returns the reconstructed visibility before any clamping.
#pragma once

#include "prefiltered/moment_state.h"
#include "gl/gl_util.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <fstream>

namespace sl::test {

struct MomentCase {
  float z1 = 0, z2 = 1, fraction = 1, receiver = 0;
};

class MomentProbe {
 public:
  explicit MomentProbe(GlHarness& h) : h_(h) {}

  // Visibility of every case for the technique `preset` with `sets` overrides.
  std::vector<float> visibility(const std::string& preset, const std::vector<std::string>& sets,
                                const std::vector<MomentCase>& cases) {
    std::vector<float> rgba = run(preset, sets, cases, "probe_moments.frag"), out;
    for (size_t i = 0; i < rgba.size(); i += 4) out.push_back(rgba[i]);
    return out;
  }

  // A soft representation's representationBlocker of every case: (fraction, depth) pairs.
  std::vector<std::pair<float, float>> blocker(const std::string& preset, const std::vector<std::string>& sets,
                                               const std::vector<MomentCase>& cases) {
    std::vector<float> rgba = run(preset, sets, cases, "probe_blocker.frag");
    std::vector<std::pair<float, float>> out;
    for (size_t i = 0; i < rgba.size(); i += 4) out.emplace_back(rgba[i], rgba[i + 1]);
    return out;
  }

 private:
  std::vector<float> run(const std::string& preset, const std::vector<std::string>& sets,
                         const std::vector<MomentCase>& cases, const std::string& fragment) {
    Technique t = makeTechnique(preset, sets);
    auto state = t.representation->createState();
    state->configure(t.params);
    const std::string prelude = state->defines() + "#include \"" + t.representation->glslModule() + "\"\n";
    Program& p = h_.shaders.get({"moment probe " + fragment + " " + preset,
                                 {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, fragment}},
                                 prelude});
    EXPECT_TRUE(p.valid()) << p.error();
    if (!p.valid()) return {};
    const int w = static_cast<int>(cases.size());
    Texture2D input(GL_RGBA32F, w, 1, "probe cases");
    glTextureSubImage2D(input.id(), 0, 0, 0, w, 1, GL_RGBA, GL_FLOAT, cases.data());
    Texture2D target(GL_RGBA32F, w, 1, "probe result");
    Framebuffer fbo("probe");
    fbo.attach({&target}, nullptr);
    fbo.bind();
    p.use();
    setTechniqueUniforms(p, t, LightSpace{}, Light{});
    {
      TextureUnits units;
      units.bind(p, "u_cases", input.id());
      drawFullscreenTriangle();
    }
    return target.readFloats(4);
  }

 public:
  // representationMoments(z) of every target, 4 floats each.
  std::vector<float> moments(const std::string& preset, const std::vector<std::string>& sets, float z) {
    Technique t = makeTechnique(preset, sets);
    auto state = t.representation->createState();
    state->configure(t.params);
    const std::string prelude = state->defines() + "#include \"" + t.representation->glslModule() + "\"\n";
    Program& p =
        h_.shaders.get({"moment probe moments " + preset,
                        {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "probe_write.frag"}},
                        prelude});
    EXPECT_TRUE(p.valid()) << p.error();
    if (!p.valid()) return {};
    Texture2D target(GL_RGBA32F, 8, 1, "probe moments");
    Framebuffer fbo("probe");
    fbo.attach({&target}, nullptr);
    fbo.bind();
    p.use();
    setTechniqueUniforms(p, t, LightSpace{}, Light{});
    p.set("u_depth", z);
    drawFullscreenTriangle();
    std::vector<float> out = target.readFloats(4);
    out.resize(4 * static_cast<size_t>(dynamic_cast<MomentMapState&>(*state).config().targets()));
    return out;
  }

  static std::string writeSource() {
    return R"(// representationMoments(u_depth), target x at pixel x.
uniform float u_depth;
layout(location = 0) out vec4 o_result;
void main() {
  vec4 m[SL_MOMENT_TARGETS];
  representationMoments(sanitizeDepth(u_depth), m);
  o_result = m[min(int(gl_FragCoord.x), SL_MOMENT_TARGETS - 1)];
}
)";
  }

  // result: what the probe writes from the filtered moments m of case c.
  static std::string probeSource(const std::string& result = "vec4(representationFromMoments(m, c.w), 0.0, 0.0, 1.0)") {
    return R"(// Probe of a pre-filtered representation (techniques/prefiltered/tests/moment_probe.h).
uniform sampler2D u_cases;
layout(location = 0) out vec4 o_result;

vec4 quantize(vec4 v) {
#if SL_MOMENT_FLOAT_BITS == 16
  return vec4(unpackHalf2x16(packHalf2x16(v.xy)), unpackHalf2x16(packHalf2x16(v.zw)));
#else
  return v;
#endif
}

void main() {
  vec4 c = texelFetch(u_cases, ivec2(gl_FragCoord.xy), 0);
  vec4 a[SL_MOMENT_TARGETS], b[SL_MOMENT_TARGETS], m[SL_MOMENT_TARGETS];
  representationMoments(sanitizeDepth(c.x), a);
  representationMoments(sanitizeDepth(c.y), b);
  for (int t = 0; t < SL_MOMENT_TARGETS; ++t) {
    a[t] = quantize(a[t]);
    b[t] = quantize(b[t]);
#ifdef SL_MOMENT_LOG_FILTER
    vec4 big = max(a[t], b[t]);
    m[t] = big + log(c.z * exp(u_esm_exponent * (a[t] - big)) + (1.0 - c.z) * exp(u_esm_exponent * (b[t] - big))) /
                     u_esm_exponent;
#else
    m[t] = mix(b[t], a[t], c.z);
#endif
    m[t] = quantize(m[t]);
  }
  o_result = )" +
           result + R"(;
}
)";
  }

 private:
  GlHarness& h_;
};

// A shader folder with the probe added (the source tree is never written).
// One folder per test: ctest runs tests in parallel processes, and a shared folder would be
// removed and copied again under a running test.
inline std::string probeShaderDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string dir = copyShaders(std::string("moment_probe_") + (info ? info->name() : "none"));
  std::ofstream(std::filesystem::path(dir) / "probe_moments.frag") << MomentProbe::probeSource();
  std::ofstream(std::filesystem::path(dir) / "probe_write.frag") << MomentProbe::writeSource();
  std::ofstream(std::filesystem::path(dir) / "probe_blocker.frag")
      << MomentProbe::probeSource("vec4(representationBlocker(m, c.w), 0.0, 1.0)");
  // The filtered lookup (momentsAt) at every texel centre of layer 0: target 0.
  std::ofstream(std::filesystem::path(dir) / "probe_lookup.frag") << R"(uniform vec2 u_probeSize;
layout(location = 0) out vec4 o_result;
void main() {
  vec4 m[SL_MOMENT_TARGETS];
  momentsAt(vec3(gl_FragCoord.xy / u_probeSize, 0.0), m);
  o_result = m[0];
}
)";
  return dir;
}

}  // namespace sl::test
