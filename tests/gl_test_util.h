// Helpers for GPU tests: a headless context, one renderer, small frames, and readbacks.
#pragma once

#include "gl/gl_util.h"
#include "gl/headless_context.h"
#include "metrics/metrics.h"
#include "reference/reference.h"
#include "render/renderer.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
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
    renderer.validateFrameGraph = true;  // every frame's wiring checked before it runs
  }
  // Strict mode for uniforms: a `u_*` uniform that a program reads but nothing sets fails the
  // test (in the program it is only a warning). A test that misspells one on purpose clears
  // this after checking the report.
  bool requireAllUniformsSet = true;
  ~GlHarness() {
    shaders.checkUnsetUniforms();
    if (!requireAllUniformsSet) return;
    for (const auto& r : shaders.unsetUniformReports()) ADD_FAILURE() << r;
  }
};

struct Frame {
  int width = 0, height = 0;
  std::vector<float> visibility;  // 2 channels: visibility, confidence
  std::vector<float> position;    // 4 channels, w = covered
  std::vector<float> normal;      // 4 channels
  std::vector<uint32_t> surface;  // 4 channels: instance + 1, triangle, packed facet, 0
  GBufferView gbuffer() const { return GBufferView{width, height, position.data(), normal.data(), surface.data()}; }
  float at(int x, int y) const { return visibility[2 * (static_cast<size_t>(y) * width + x)]; }
  // The visibility channel alone, and 1 where the G-buffer covers the pixel (the metrics' mask).
  std::vector<float> visibilityChannel() const {
    std::vector<float> v(visibility.size() / 2);
    for (size_t i = 0; i < v.size(); ++i) v[i] = visibility[2 * i];
    return v;
  }
  std::vector<uint8_t> covered() const {
    std::vector<uint8_t> c(position.size() / 4);
    for (size_t i = 0; i < c.size(); ++i) c[i] = position[4 * i + 3] > 0.5f;
    return c;
  }
  long long nonfinite() const {
    long long n = 0;
    for (size_t i = 0; i < visibility.size(); i += 2) n += std::isfinite(visibility[i]) ? 0 : 1;
    return n;
  }
};

// A technique from parts (presets fix the layout; these must work under every layout).
inline Technique compose(const std::string& layout, const std::string& representation, const std::string& accumulation,
                         const std::vector<std::string>& sets) {
  Technique t;
  t.presetId = representation;
  t.layout = findLayout(layout);
  t.representation = findRepresentation(representation);
  t.accumulation = findAccumulation(accumulation);
  std::vector<ParamDecl> decls = commonParams();
  for (auto&& part : {t.layout->params(), t.representation->params(), t.accumulation->params()})
    decls.insert(decls.end(), part.begin(), part.end());
  t.params = ParamSet(std::move(decls));
  for (const auto& s : sets) t.params.setAssignment(s);
  return t;
}

inline Frame readFrame(const Renderer& r, const Viewport& vp, int w, int h) {
  Frame f;
  f.width = w;
  f.height = h;
  f.visibility = vp.visibilityTexture()->readFloats(2);
  f.position = r.gPosition().readFloats(4);
  f.normal = r.gNormal().readFloats(4);
  f.surface = r.gSurface().readUints(4);
  return f;
}

// The frame's visibility against the ray-traced reference at the same G-buffer points.
inline ErrorMetrics visibilityError(const ReferenceTracer& tracer, const Frame& f,
                                    const ReferenceOptions& options = {}) {
  const std::vector<float> ref = tracer.visibility(f.gbuffer(), options);
  const std::vector<float> vis = f.visibilityChannel();
  const std::vector<uint8_t> valid = f.covered();
  return compareVisibility(vis.data(), ref.data(), valid.data(), vis.size());
}
inline ErrorMetrics visibilityError(const Scene& scene, const Frame& f, double time = 0.0) {
  ReferenceOptions options;
  options.time = time;
  return visibilityError(ReferenceTracer(scene, time), f, options);
}

// The percentage of pixels whose visibility is wrong against the ray-traced reference.
inline double wrongPct(const Scene& scene, const Frame& f) { return visibilityError(scene, f).wrongPixelPct; }

// `frames` frames of `vp` from a cut (default two, as the bench's --warmup 1 --frames 1:
// accumulations have one frame of history, as a user sees them a moment after a cut).
inline void renderFromCut(GlHarness& h, FrameInput in, Viewport& vp, int frames = 2) {
  for (int f = 0; f < frames; ++f) {
    in.cut = f == 0;
    h.renderer.render(in, {&vp});
  }
}

// One frame of `vp` from the scene's first camera (the scene set on h.renderer); the shaders
// must build.
inline void renderFirstCamera(GlHarness& h, const Scene& scene, Viewport& vp, int w, int hgt) {
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = w;
  in.height = hgt;
  h.renderer.render(in, {&vp});
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

// One frame of `preset` (with `sets`) from the scene's first camera, read back with its G-buffer.
inline Frame renderOnce(GlHarness& h, const Scene& scene, const std::string& preset,
                        const std::vector<std::string>& sets, int w, int hgt) {
  h.renderer.setScene(scene);
  Viewport vp(makeTechnique(preset, sets));
  renderFirstCamera(h, scene, vp, w, hgt);
  return readFrame(h.renderer, vp, w, hgt);
}

// The shadow map's depth (every layer, rows bottom-up) after one 160x90 frame of `preset` from
// the scene's first camera; the scene must be set on h.renderer.
inline std::vector<float> renderShadowDepth(GlHarness& h, const Scene& scene, const std::string& preset,
                                            const std::vector<std::string>& sets) {
  Viewport vp(makeTechnique(preset, sets));
  renderFirstCamera(h, scene, vp, 160, 90);
  return vp.representation->depthTexture()->readFloats(1);
}

// Copies the shader folder to a temp dir (hot-reload tests edit the copy, never the source).
inline std::string copyShaders(const std::string& name) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::copy(defaultShaderDir(), dir, std::filesystem::copy_options::recursive);
  return dir.string();
}

// Replaces the first `from` with `to`; makes sure the modification time moves even on
// coarse-grained file systems, so the shader library sees the change.
inline void rewriteFile(const std::filesystem::path& p, const std::string& from, const std::string& to) {
  std::stringstream s;
  s << std::ifstream(p).rdbuf();
  std::string text = s.str();
  auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  auto before = std::filesystem::last_write_time(p);
  std::ofstream(p, std::ios::trunc) << text;
  if (std::filesystem::last_write_time(p) == before)
    std::filesystem::last_write_time(p, before + std::chrono::seconds(1));
}

// 1-based number of the first line containing `needle` (0 = none).
inline int lineOf(const std::filesystem::path& p, const std::string& needle) {
  std::ifstream in(p);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.find(needle) != std::string::npos) return n;
  return 0;
}

inline std::string writeTempFile(const std::string& name, const std::string& text) {
  std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace sl::test
