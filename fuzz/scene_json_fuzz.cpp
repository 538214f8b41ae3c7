// libFuzzer target: JSON scene text (assets/scenes/*.json format) through loadScene.
#include "fuzz_scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  sl::fuzz::loadSceneBytes(data, size, ".json");
  return 0;
}
