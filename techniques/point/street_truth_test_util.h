// What the point family's GL tests measure against, as the bench does: street's first camera at
// a size, its ray-traced reference (16 samples, cached), and a viewport rendered two frames from
// a cut.
#pragma once

#include "bench/reference_cache.h"
#include "tests/assets_dir.h"
#include "tests/gl_test_util.h"

#include <gtest/gtest.h>

#include <string>

namespace sl::test {

struct StreetTruth {
  Scene scene;
  FrameInput in;
  ReferenceImage reference;
};

inline StreetTruth streetTruth(GlHarness& h, int width, int height) {
  StreetTruth t{loadScene("street", kAssets), {}, {}};
  h.renderer.setScene(t.scene);
  t.in.camera = t.scene.cameras.front();
  t.in.width = width;
  t.in.height = height;
  ReferenceSettings rs;
  rs.samples = 16;
  t.reference = ReferenceCache(t.scene, rs).forFrame(h.renderer, t.in);
  return t;
}

// Two frames from a cut, as the bench's --warmup 1 --frames 1.
inline void renderFromCut(GlHarness& h, FrameInput in, Viewport& vp) {
  for (int frame = 0; frame < 2; ++frame) {
    in.cut = frame == 0;
    h.renderer.render(in, {&vp});
  }
}

// A preset's id as a test-name suffix (gtest allows no '-').
inline std::string presetTestName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& ch : name)
    if (ch == '-') ch = '_';
  return name;
}

}  // namespace sl::test
