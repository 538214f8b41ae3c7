// What the point family's GL tests measure against, as the bench does: street's first camera at
// a size and its ray-traced reference (16 samples, cached); viewports are rendered two frames
// from a cut (test::renderFromCut).
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

// A preset's id as a test-name suffix (gtest allows no '-').
inline std::string presetTestName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& ch : name)
    if (ch == '-') ch = '_';
  return name;
}

}  // namespace sl::test
