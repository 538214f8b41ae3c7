// Shared by the scene fuzz targets: the loaders take paths (the extension picks the format and
// a scene's models resolve relative to its folder), so each input is written to a private
// temporary file and loaded from there. A SceneError (or any std::exception) is the expected
// answer to bad input; a crash, sanitizer report, leak or hang is a bug.
#pragma once

#include "scene/scene.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

namespace sl::fuzz {

inline std::string scratchDir() {
  static const std::string dir = [] {
    const auto d = std::filesystem::temp_directory_path() / ("shadowlab-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d.string();
  }();
  return dir;
}

inline void loadSceneBytes(const uint8_t* data, size_t size, const char* extension) {
  const std::string path = scratchDir() + "/input" + extension;
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    if (size) std::fwrite(data, 1, size, f);
    std::fclose(f);
  }
  try {
    Scene scene = loadScene(path, SHADOWLAB_SOURCE_DIR "/assets");
    (void)scene.triangleCount();
  } catch (const std::exception&) {
    // Rejected with a message: what bad input must get.
  }
}

}  // namespace sl::fuzz
