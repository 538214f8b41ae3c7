// filter.skip_unread: the blur filters only the texels a visible receiver can read (the focused
// fit's receiver hull, blur_spans.h). The picture must not change: each case renders a preset
// with the skip on and off and compares the visibility bit for bit, and checks that the skip
// left part of the map unfiltered (the status line's share), so a hull that covered every
// texel would fail here rather than pass as a saving.
#include "tests/gl_test_util.h"

#include <cstdio>

namespace sl {
namespace {

struct SkipCase {
  std::string scene, preset;
  double maxPct;  // the share of the map the blur may filter: the hull must leave texels out
};
void PrintTo(const SkipCase& c, std::ostream* os) { *os << c.scene << " " << c.preset; }

// The percentage in "blur over N % of the map", or -1 where the status has none.
double filteredPct(const std::string& status) {
  const size_t at = status.find("blur over ");
  double pct = -1.0;
  if (at != std::string::npos) std::sscanf(status.c_str() + at, "blur over %lf", &pct);
  return pct;
}

class PrefilteredSkipUnread : public ::testing::TestWithParam<SkipCase> {};

TEST_P(PrefilteredSkipUnread, TheSameVisibilityFromPartOfTheMap) {
  test::GlHarness h;
  const Scene scene = loadScene(GetParam().scene, defaultAssetsDir());
  h.renderer.setScene(scene);
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 160;
  in.height = 90;
  std::vector<float> seen[2];
  for (int skip : {0, 1}) {
    Viewport vp(makeTechnique(GetParam().preset, {"shadowmap.size=512", "filter.skip_unread=" + std::to_string(skip)}));
    h.renderer.render(in, {&vp});
    seen[skip] = test::readFrame(h.renderer, vp, in.width, in.height).visibilityChannel();
    const double pct = filteredPct(vp.status());
    if (skip) {
      std::printf("%s %s: %s\n", GetParam().scene.c_str(), GetParam().preset.c_str(), vp.status().c_str());
      EXPECT_GT(pct, 5.0) << vp.status();
      EXPECT_LT(pct, GetParam().maxPct) << vp.status();
    } else {
      EXPECT_EQ(pct, -1.0) << vp.status();
    }
  }
  EXPECT_TRUE(h.shaders.errors().empty());
  ASSERT_EQ(seen[0].size(), seen[1].size());
  long long differ = 0;
  for (size_t i = 0; i < seen[0].size(); ++i) differ += seen[0][i] != seen[1][i];
  EXPECT_EQ(differ, 0) << "pixels whose visibility changed when the blur skipped unread texels";
}

INSTANTIATE_TEST_SUITE_P(Cases, PrefilteredSkipUnread,
                         ::testing::Values(SkipCase{"basic", "vsm", 80}, SkipCase{"basic", "esm", 80},
                                           SkipCase{"basic", "msm", 80}, SkipCase{"basic", "lvsm", 80},
                                           SkipCase{"basic", "convolution", 80}, SkipCase{"spotlight", "vsm", 100.5},
                                           SkipCase{"terrain", "evsm4", 80}),
                         [](const auto& info) {
                           std::string name = info.param.scene + "_" + info.param.preset;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

}  // namespace
}  // namespace sl
