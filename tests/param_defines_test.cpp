// Enum parameters reach GLSL as the define of their chosen value (core/params.h enumDefines), so
// a shader names a choice, never its position in the list. These tests hold every such name a
// shader uses to the declarations: a renamed or reordered choice fails here, not silently on
// screen.
#include "tests/assets_dir.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace sl {
namespace {

namespace fs = std::filesystem;

// Every enum declared by a part or in common, with its choices (keys shared by parts merged).
std::map<std::string, std::set<std::string>> everyEnum() {
  std::map<std::string, std::set<std::string>> out;
  auto add = [&](const std::vector<ParamDecl>& decls) {
    for (const ParamDecl& d : decls)
      if (d.type == ParamType::Enum)
        for (const auto& c : d.choices) out[d.key].insert(c);
  };
  add(commonParams());
  for (const Layout* l : allLayouts()) add(l->params());
  for (const Representation* r : allRepresentations()) add(r->params());
  for (const Accumulation* a : allAccumulations()) add(a->params());
  return out;
}

// Every SL_ identifier in the shader tree, with the file that first names it.
std::map<std::string, std::string> shaderIdentifiers() {
  std::map<std::string, std::string> out;
  const std::regex word("SL_[A-Z0-9_]+");
  for (const auto& e : fs::recursive_directory_iterator(fs::path(SHADOWLAB_SOURCE_DIR) / "shaders")) {
    if (!e.is_regular_file()) continue;
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    for (std::sregex_iterator it(s.begin(), s.end(), word), end; it != end; ++it)
      out.emplace(it->str(), e.path().filename().string());
  }
  return out;
}

TEST(ParamDefines, ChoiceNamesFollowTheDeclaration) {
  EXPECT_EQ(choiceDefineName("bias.mode", "normal-offset"), "SL_BIAS_MODE_NORMAL_OFFSET");
  ParamSet params(commonParams());
  params.setAssignment("bias.mode=receiver-plane");
  EXPECT_NE(enumDefines(params).find("#define SL_BIAS_MODE_IS_RECEIVER_PLANE\n"), std::string::npos);
  EXPECT_EQ(enumDefines(params).find("SL_BIAS_MODE_IS_SLOPE"), std::string::npos) << "only the chosen value";
}

TEST(ParamDefines, EveryChoiceAShaderNamesIsDeclared) {
  const auto enums = everyEnum();
  const auto identifiers = shaderIdentifiers();
  ASSERT_TRUE(identifiers.count("SL_BIAS_MODE_IS_RECEIVER_PLANE")) << "the scan finds nothing";
  int checked = 0;
  for (const auto& [key, choices] : enums) {
    const std::string prefix = choiceDefineName(key, "");  // "SL_BIAS_MODE_"
    std::set<std::string> names;
    // A chosen value's flag (SL_<KEY>_IS_<CHOICE>, enumDefines) or a choice's index constant
    // (SL_<KEY>_<CHOICE>, as the virtual layout defines them for a uniform comparison).
    for (const auto& c : choices) names.insert({choiceDefineName(key, c), choiceDefineName(key, "is." + c)});
    for (const auto& [id, file] : identifiers) {
      EXPECT_NE(id, prefix.substr(0, prefix.size() - 1))
          << file << " tests " << id << " by value: name the choice (" << prefix << "<CHOICE>)";
      if (id.rfind(prefix, 0) != 0 || id.back() == '_') continue;  // "SL_X_<CHOICE>" in a comment
      ++checked;
      EXPECT_TRUE(names.count(id)) << file << " names " << id << ", which is no choice of " << key;
    }
  }
  EXPECT_GE(checked, 4) << "bias.mode's names alone are four";
}

}  // namespace
}  // namespace sl
