// Scene effects (no GPU): an area light is what makes a scene call for soft shadows, and the
// light radius is validated where the scene is read.
#include "scene/scene.h"
#include "scene/scene_effects.h"
#include "gl/shader_library.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace sl {
namespace {

namespace fs = std::filesystem;

std::string writeScene(const std::string& name, const std::string& light) {
  const fs::path dir = fs::temp_directory_path() / ("shadowlab_soft_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p) << R"({"objects":[{"shape":"plane","size":[10,10]}],"light":)" << light << "}";
  return p.string();
}

TEST(SceneEffects, AreaLightFollowsTheRadius) {
  Scene s;
  EXPECT_FALSE(sceneEffects(s).areaLight);
  EXPECT_EQ(hardShadowNote(sceneEffects(s)), "");
  s.light.radius = 0.05f;
  const SceneEffects fx = sceneEffects(s);
  EXPECT_TRUE(fx.areaLight);
  EXPECT_FLOAT_EQ(fx.lightRadius, 0.05f);
  EXPECT_EQ(hardShadowNote(fx), "hard: ignores light radius 0.05");
  s.light.radius = std::nanf("");  // never from a file (validation), but never an area light of NaN size
  EXPECT_FALSE(sceneEffects(s).areaLight);
}

TEST(SceneEffects, BuiltinSoftScenesHaveAnAreaLight) {
  for (const char* id : {"soft", "contact"}) {
    const Scene s = loadScene(id, defaultAssetsDir());
    EXPECT_TRUE(sceneEffects(s).areaLight) << id;
  }
  EXPECT_FALSE(sceneEffects(loadScene("basic", defaultAssetsDir())).areaLight);
}

TEST(SceneEffects, BadLightRadiusIsASceneErrorNamingFileAndKey) {
  for (const auto& [name, light] :
       std::vector<std::pair<std::string, std::string>>{{"neg.json", R"({"radius":-0.1})"},
                                                        {"huge.json", R"({"radius":1e300})"},
                                                        {"text.json", R"({"radius":"big"})"}}) {
    const std::string path = writeScene(name, light);
    try {
      loadScene(path, defaultAssetsDir());
      ADD_FAILURE() << name << " loaded";
    } catch (const SceneError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(name), std::string::npos) << msg;
      EXPECT_NE(msg.find("light.radius"), std::string::npos) << msg;
    }
  }
  // Large but finite is a valid (very soft) light.
  EXPECT_FLOAT_EQ(loadScene(writeScene("big.json", R"({"radius":50})"), defaultAssetsDir()).light.radius, 50.0f);
}

}  // namespace
}  // namespace sl
