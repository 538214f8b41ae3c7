// Every input under tests/fuzz-regressions/ (fuzz seeds and inputs that once crashed a loader,
// found by scripts/fuzz.sh) goes through loadScene in the normal build: it must load or be
// rejected with a SceneError naming the file, never crash.
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace sl {
namespace {

namespace fs = std::filesystem;

TEST(SceneFuzzRegressions, EveryKeptInputLoadsOrIsRejectedWithItsFileName) {
  const fs::path root = fs::path(SHADOWLAB_SOURCE_DIR) / "tests" / "fuzz-regressions";
  int inputs = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    const std::string path = entry.path().string();
    const std::string ext = entry.path().extension().string();
    if (ext != ".json" && ext != ".gltf" && ext != ".glb") continue;
    ++inputs;
    try {
      Scene scene = loadScene(path, SHADOWLAB_SOURCE_DIR "/assets");
      EXPECT_FALSE(scene.cameras.empty()) << path;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(entry.path().filename().string()), std::string::npos) << e.what();
    }
  }
  EXPECT_GE(inputs, 1) << "no inputs under " << root;
}

TEST(SceneFuzzRegressions, TheEmbeddedTriangleSeedReachesTheMeshImport) {
  // The glTF seed keeps its buffer in a data: URI, so the fuzzer gets past file lookup into
  // accessors and indices; it must load as exactly one triangle.
  const Scene scene =
      loadScene(SHADOWLAB_SOURCE_DIR "/tests/fuzz-regressions/gltf/seed-triangle.gltf", SHADOWLAB_SOURCE_DIR "/assets");
  EXPECT_EQ(scene.triangleCount(), 1u);
}

}  // namespace
}  // namespace sl
