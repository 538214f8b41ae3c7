// libFuzzer target: glTF 2.0 (JSON .gltf; buffers it names resolve beside the input, so the
// corpus's real files exercise the full path) through tinygltf and the scene's glTF import.
#include "fuzz_scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // A leading 'g' of "glTF" is binary glTF: give it the extension its loader expects.
  const bool binary = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
  sl::fuzz::loadSceneBytes(data, size, binary ? ".glb" : ".gltf");
  return 0;
}
