// What the point family's GL tests measure against, as the bench does: street's first camera at
// a size and its ray-traced reference (16 samples, cached); viewports are rendered two frames
// from a cut (test::renderFromCut).
#pragma once

#include "tests/scene_truth_test_util.h"

#include <gtest/gtest.h>

#include <string>

namespace sl::test {

using StreetTruth = SceneTruth;

inline StreetTruth streetTruth(GlHarness& h, int width, int height) { return sceneTruth(h, "street", width, height); }

// A preset's id as a test-name suffix (gtest allows no '-').
inline std::string presetTestName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& ch : name)
    if (ch == '-' || ch == '@') ch = '_';
  return name;
}

}  // namespace sl::test
