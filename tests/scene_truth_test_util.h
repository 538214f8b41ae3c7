// What GL tests measure against, as the bench does: a builtin scene's first camera at a size and
// its ray-traced reference (16 samples, cached; every light's in a scene of several).
#pragma once

#include "bench/reference_cache.h"
#include "tests/assets_dir.h"
#include "tests/gl_test_util.h"

#include <string>

namespace sl::test {

struct SceneTruth {
  Scene scene;
  FrameInput in;
  ReferenceImage reference;
};

inline SceneTruth sceneTruth(GlHarness& h, const std::string& id, int width, int height) {
  SceneTruth t{loadScene(id, kAssets), {}, {}};
  h.renderer.setScene(t.scene);
  t.in.camera = t.scene.cameras.front();
  t.in.width = width;
  t.in.height = height;
  ReferenceSettings rs;
  rs.samples = 16;
  t.reference = ReferenceCache(t.scene, rs).forFrame(h.renderer, t.in);
  return t;
}

}  // namespace sl::test
