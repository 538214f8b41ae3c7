#include "param_hints.h"
#include "technique.h"

#include <gtest/gtest.h>

namespace sl {

namespace {

// What makeTechnique says about one override ("no error" when it takes it).
std::string overrideError(const std::string& preset, const std::string& kv) {
  try {
    makeTechnique(preset, {kv});
  } catch (const ParamError& e) {
    return std::string(e.what());
  }
  return std::string("no error");
}

}  // namespace

TEST(Params, PresetsResolveAndOverridesValidate) {
  Technique t = makeTechnique("pcf", {"shadowmap.size=512", "bias.mode=normal-offset"});
  EXPECT_EQ(t.layout->id(), "focused");
  EXPECT_EQ(t.representation->id(), "depth-pcf");
  EXPECT_EQ(t.params.i("shadowmap.size"), 512);
  EXPECT_EQ(t.params.choice("bias.mode"), "normal-offset");
  EXPECT_EQ(t.params.i("pcf.kernel"), 3);
}

TEST(Params, BadValuesAreNamed) {
  EXPECT_NE(overrideError("standard", "shadowmap.size=20").find("outside 64..8192"), std::string::npos);
  EXPECT_NE(overrideError("standard", "shadowmap.size=abc").find("not a number"), std::string::npos);
  EXPECT_NE(overrideError("standard", "bias.mode=huge").find("none|constant|slope|normal-offset"), std::string::npos);
  EXPECT_NE(overrideError("standard", "pcf.kernel=3").find("unknown parameter 'pcf.kernel'"), std::string::npos);
  EXPECT_NE(overrideError("standard", "noequals").find("key=value"), std::string::npos);
  EXPECT_NE(overrideError("standard", "bias.slope=nan").find("finite"), std::string::npos);
  EXPECT_NE(overrideError("nosuch", "a=b").find("unknown technique"), std::string::npos);
}

// The every-preset sweep's ctests (CMakeLists.txt) pick a scene's presets by first letter, a-l
// and m-z: an id starting otherwise would be tested by neither.
TEST(Params, PresetIdsStartWithALowerCaseLetter) {
  for (const auto& preset : allPresets())
    EXPECT_TRUE(!preset.id.empty() && preset.id[0] >= 'a' && preset.id[0] <= 'z') << preset.id;
}

// A key another preset declares names those presets; a typo gets the nearest key.
TEST(Params, UnknownKeysNameThePresetsThatDeclareThemOrTheNearestKey) {
  const std::string other = overrideError("standard", "pcf.kernel=5");
  EXPECT_NE(other.find("declared by the presets pcf"), std::string::npos) << other;
  EXPECT_NE(other.find("--technique"), std::string::npos) << other;
  EXPECT_EQ(other.find("standard,"), std::string::npos) << other;  // not by standard itself
  const std::string typo = overrideError("standard", "shadowmap.sise=512");
  EXPECT_NE(typo.find("did you mean 'shadowmap.size'?"), std::string::npos) << typo;
  const std::string nothing = overrideError("standard", "zzz.qqq=1");
  EXPECT_NE(nothing.find("see `shadowlab list`"), std::string::npos) << nothing;
  EXPECT_EQ(overrideError("pcf", "pcf.kernel=5"), "no error");
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("same", "same"), 0u);
}

TEST(Params, EveryDeclarationIsComplete) {
  for (const auto& preset : allPresets()) {
    Technique t = makeTechnique(preset.id);
    for (const auto& d : t.params.decls()) {
      EXPECT_FALSE(d.help.empty()) << d.key;
      if (d.type == ParamType::Float || d.type == ParamType::Int) {
        EXPECT_LE(d.min, d.defaultValue) << d.key;
        EXPECT_GE(d.max, d.defaultValue) << d.key;
      }
      if (d.type == ParamType::Enum) EXPECT_LT(d.defaultValue, d.choices.size()) << d.key;
      EXPECT_EQ(uniformName(d.key).find('.'), std::string::npos);
    }
  }
}

}  // namespace sl
