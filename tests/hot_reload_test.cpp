// Hot reload: a changed shader is rebuilt; a broken one keeps the last good program and the
// error names the file and line.
#include "gl_test_util.h"
#include "technique.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace sl {

namespace fs = std::filesystem;

using test::copyShaders;
using test::lineOf;

static void rewrite(const fs::path& p, const std::string& from, const std::string& to) {
  test::rewriteFile(p, from, to);
}

TEST(HotReload, ChangedIncludedFileRebuildsAndBrokenFileKeepsTheLastGoodProgram) {
  std::string dir = copyShaders("hot_reload_shaders");
  test::GlHarness h(dir);
  Scene scene = loadScene("basic", defaultAssetsDir());
  h.renderer.setScene(scene);
  Viewport vp(makeTechnique("standard", {"shadowmap.size=256"}));
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 64;
  in.height = 40;
  h.renderer.render(in, {&vp});
  ASSERT_TRUE(h.shaders.errors().empty());
  EXPECT_EQ(h.shaders.reloadChanged(), 0);

  // An included module changes: every program using it is rebuilt, the others are not.
  int before = h.shaders.buildCount();
  rewrite(fs::path(dir) / "common/bias.glsl", "float biasDepth(", "// edited\nfloat biasDepth(");
  int rebuilt = h.shaders.reloadChanged();
  EXPECT_GE(rebuilt, 1);
  EXPECT_LT(rebuilt, 4);  // gbuffer/shadow/shade do not include bias.glsl
  EXPECT_EQ(h.shaders.buildCount(), before + rebuilt);
  EXPECT_TRUE(h.shaders.errors().empty());

  // A syntax error: the error names file:line, the old program keeps rendering.
  rewrite(fs::path(dir) / "passes/forward.frag", "o_color = shadeSurface(", "o_color = shadeSurface( +* ;");
  h.shaders.reloadChanged();
  auto errors = h.shaders.errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("shaders/passes/forward.frag:"), std::string::npos) << errors[0];
  const int badLine = lineOf(fs::path(dir) / "passes/forward.frag", "+* ;");
  EXPECT_NE(errors[0].find("forward.frag:" + std::to_string(badLine) + ":"), std::string::npos) << errors[0];
  h.renderer.render(in, {&vp});
  auto pixels = vp.colorTexture()->readRgba8();
  int nonBlack = 0;
  for (size_t i = 0; i < pixels.size(); i += 4) nonBlack += pixels[i] + pixels[i + 1] + pixels[i + 2] > 30;
  EXPECT_GT(nonBlack, 64 * 40 / 2);  // the last good shade program still draws the scene

  // Fixed again: the error goes away.
  rewrite(fs::path(dir) / "passes/forward.frag", "o_color = shadeSurface( +* ;", "o_color = shadeSurface(");
  h.shaders.reloadChanged();
  EXPECT_TRUE(h.shaders.errors().empty());

  // An error inside an included module (a semantic one, which Mesa reports without the
  // module's source-string number) still names the module and its line.
  rewrite(fs::path(dir) / "common/bias.glsl", "// edited\n", "// edited\nfloat brokenOnPurpose = undefinedName;\n");
  h.shaders.reloadChanged();
  bool named = false;
  for (const auto& e : h.shaders.errors()) named |= e.find("shaders/common/bias.glsl:") != std::string::npos;
  EXPECT_TRUE(named) << (h.shaders.errors().empty() ? "no error" : h.shaders.errors().back());
  rewrite(fs::path(dir) / "common/bias.glsl", "float brokenOnPurpose = undefinedName;\n", "");

  h.shaders.reloadChanged();
  EXPECT_TRUE(h.shaders.errors().empty());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace sl
