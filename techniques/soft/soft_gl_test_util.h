// Shared by the soft techniques' GL tests (pcss, vssm, convolution-soft): one frame rendered
// after a cut, the lights from a point to a huge disk they must all survive, and the check that
// such a frame is finite, within [0,1] and shows both a shadow and lit ground.
#pragma once

#include "tests/gl_test_util.h"
#include "technique.h"

#include <algorithm>
#include <string>
#include <vector>

namespace sl::test {

inline Frame renderSoft(GlHarness& h, const Scene& scene, Viewport& vp, int w, int hgt) {
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = w;
  in.height = hgt;
  in.cut = true;
  h.renderer.render(in, {&vp});
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  return readFrame(h.renderer, vp, w, hgt);
}

// rmse against the area-light reference of `preset` at its defaults, from the scene's first camera.
inline double softRmse(GlHarness& h, const Scene& scene, const std::string& preset, int w, int hgt) {
  Viewport vp(makeTechnique(preset));
  return visibilityError(scene, renderSoft(h, scene, vp, w, hgt)).rmse;
}

struct LightCase {
  const char* scene;
  float radius;  // < 0: the scene's own
};

// Point lights, the scenes' own disks, a huge sun disk, a vanishing one, a spot from small to huge.
inline std::vector<LightCase> softLightCases() {
  return {{"basic", -1},      {"soft", -1},        {"contact", -1},     {"soft", 5.0f},
          {"contact", 1e-6f}, {"spotlight", 0.4f}, {"spotlight", 50.0f}};
}

inline Scene loadLightCase(const LightCase& c) {
  Scene scene = loadScene(c.scene, defaultAssetsDir());
  if (c.radius >= 0) scene.light.radius = c.radius;
  return scene;
}

// Every scene of softLightCases has a shadow in view and lit ground.
inline void expectFiniteShadowAndLight(const Frame& f, const std::string& what) {
  EXPECT_EQ(f.nonfinite(), 0) << what;
  float lo = 1, hi = 0;
  for (size_t i = 0; i < f.visibility.size(); i += 2) {
    lo = std::min(lo, f.visibility[i]);
    hi = std::max(hi, f.visibility[i]);
  }
  EXPECT_GE(lo, 0.0f) << what;
  EXPECT_LE(hi, 1.0f) << what;
  EXPECT_LT(lo, 0.5f) << what;
  EXPECT_GT(hi, 0.5f) << what;
}

}  // namespace sl::test
