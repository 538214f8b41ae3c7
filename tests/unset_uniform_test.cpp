// A uniform that nothing sets reads 0: the shader library reports every active `u_*` uniform
// a drawn program never had set, once, naming the program (GlHarness fails any other test
// that leaves one behind).
#include "gl_test_util.h"
#include "technique.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace sl {

using test::GlHarness;

namespace {

const char* kUnsetUniformProbe = R"(layout(location = 0) out vec4 o_color;
uniform float u_gain;
uniform float u_offest;  // misspelt: C++ sets u_offset
uniform sampler2D u_unboundTexture;
void main() { o_color = vec4(u_gain + u_offest) + texture(u_unboundTexture, vec2(0.5)); }
)";

struct ProbeTarget {
  Texture2D target{GL_RGBA8, 4, 4, "probe"};
  Framebuffer fbo{"probe"};
  GLuint vao = 0;
  ProbeTarget() {
    fbo.attach({&target}, nullptr);
    glCreateVertexArrays(1, &vao);
  }
  ~ProbeTarget() { glDeleteVertexArrays(1, &vao); }
  void draw(const Program& p) {
    fbo.bind();
    p.use();
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
  }
};

bool mentions(const std::vector<std::string>& reports, const std::string& a, const std::string& b) {
  return std::any_of(reports.begin(), reports.end(), [&](const std::string& r) {
    return r.find(a) != std::string::npos && r.find(b) != std::string::npos;
  });
}

}  // namespace

TEST(UnsetUniforms, MisspeltUniformIsReportedOnceNamingProgramAndUniform) {
  const std::string dir = test::copyShaders("unset_uniform_probe");
  std::ofstream(std::filesystem::path(dir) / "probe_unset.frag") << kUnsetUniformProbe;
  GlHarness h(dir);
  h.requireAllUniformsSet = false;  // this test leaves them unset on purpose
  Program& p = h.shaders.get(
      {"probe", {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "probe_unset.frag"}}, ""});
  ASSERT_TRUE(p.valid()) << p.error();
  EXPECT_TRUE(h.shaders.checkUnsetUniforms().empty()) << "a program nothing drew with is not checked";
  ProbeTarget probe;
  p.use();
  p.set("u_gain", 1.0f);
  p.set("u_offset", 0.5f);  // the typo's other half: sets nothing
  probe.draw(p);
  testing::internal::CaptureStderr();
  std::vector<std::string> found = h.shaders.checkUnsetUniforms();
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(found.size(), 2u);
  EXPECT_TRUE(mentions(found, "'probe'", "'u_offest'"));
  EXPECT_TRUE(mentions(found, "'probe'", "'u_unboundTexture'"));
  EXPECT_FALSE(mentions(found, "probe", "u_gain"));
  EXPECT_NE(err.find("u_offest"), std::string::npos) << err;
  // Once: drawing again, or rebuilding the program, says nothing new.
  probe.draw(p);
  EXPECT_TRUE(h.shaders.checkUnsetUniforms().empty());
  test::rewriteFile(std::filesystem::path(dir) / "probe_unset.frag", "u_gain + u_offest", "u_offest + u_gain");
  EXPECT_EQ(h.shaders.reloadChanged(), 1);
  p.set("u_gain", 1.0f);
  probe.draw(p);
  EXPECT_TRUE(h.shaders.checkUnsetUniforms().empty());
  EXPECT_EQ(h.shaders.unsetUniformReports().size(), 2u);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(UnsetUniforms, SettingEveryUniformReportsNothing) {
  const std::string dir = test::copyShaders("unset_uniform_probe_ok");
  std::ofstream(std::filesystem::path(dir) / "probe_unset.frag") << kUnsetUniformProbe;
  GlHarness h(dir);
  Program& p = h.shaders.get(
      {"probe", {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "probe_unset.frag"}}, ""});
  ASSERT_TRUE(p.valid()) << p.error();
  ProbeTarget probe;
  p.set("u_gain", 1.0f);
  p.set("u_offest", 0.5f);
  p.set("u_unboundTexture", 0);
  probe.draw(p);
  EXPECT_TRUE(h.shaders.checkUnsetUniforms().empty());
}

TEST(UnsetUniforms, RendererReportsATypoInATechniqueModule) {
  // The failure this exists for: a parameter's uniform misspelt in GLSL reads 0 (here: no
  // slope bias at all) and every picture still looks plausible.
  const std::string dir = test::copyShaders("unset_uniform_bias");
  test::rewriteFile(std::filesystem::path(dir) / "common" / "bias.glsl", "uniform float u_bias_slope;",
                    "uniform float u_bias_slpoe;");
  test::rewriteFile(std::filesystem::path(dir) / "common" / "bias.glsl", "float texels = u_bias_slope",
                    "float texels = u_bias_slpoe");
  GlHarness h(dir);
  h.requireAllUniformsSet = false;
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  Viewport vp(makeTechnique("standard", {"shadowmap.size=256", "bias.mode=slope"}));
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 64;
  in.height = 40;
  h.renderer.render(in, {&vp});
  h.renderer.render(in, {&vp});
  EXPECT_TRUE(h.shaders.errors().empty());
  const auto& reports = h.shaders.unsetUniformReports();
  EXPECT_EQ(reports.size(), 1u);  // the forward program; the shadow pass does not read it
  EXPECT_TRUE(mentions(reports, "'forward focused+depth-nearest'", "'u_bias_slpoe'"))
      << (reports.empty() ? "no report" : reports.front());
}

}  // namespace sl
