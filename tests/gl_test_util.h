// Helpers for GPU tests: a headless context, one renderer, small frames, and readbacks.
#pragma once

#include "gl/gl_util.h"
#include "gl/headless_context.h"
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace sl::test {

struct GlHarness {
  HeadlessContext context;
  ShaderLibrary shaders;
  Renderer renderer;
  explicit GlHarness(const std::string& shaderDir = defaultShaderDir()) : shaders(shaderDir), renderer(shaders) {
    enableGlDebugOutput(true);
    resetGlDebugErrorCount();
  }
};

struct Frame {
  int width = 0, height = 0;
  std::vector<float> visibility;  // 2 channels: visibility, confidence
  std::vector<float> position;    // 4 channels, w = covered
  std::vector<float> normal;      // 4 channels
  float at(int x, int y) const { return visibility[2 * (static_cast<size_t>(y) * width + x)]; }
  long long nonfinite() const {
    long long n = 0;
    for (size_t i = 0; i < visibility.size(); i += 2) n += std::isfinite(visibility[i]) ? 0 : 1;
    return n;
  }
};

inline Frame readFrame(const Renderer& r, const Viewport& vp, int w, int h) {
  Frame f;
  f.width = w;
  f.height = h;
  f.visibility = vp.visibilityTexture()->readFloats(2);
  f.position = r.gPosition().readFloats(4);
  f.normal = r.gNormal().readFloats(4);
  return f;
}

inline std::string writeTempFile(const std::string& name, const std::string& text) {
  std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace sl::test
