// The numerically hard cases for every layout (llvmpipe, small frames): no NaN/Inf,
// visibility in [0, 1], no GL error, and no layout much worse than the focused map at the same
// texel count (a warp or partition must degrade to focusing, never to garbage).
#include "metrics/metrics.h"
#include "reference/reference.h"
#include "layouts/hard_cases.h"
#include "tests/gl_test_util.h"
#include "technique.h"

namespace sl {
namespace {

using test::wrongPct;

// Runs `preset` with `sets` on the case; checks the frame and returns its wrong pixels.
double runCase(test::GlHarness& h, const Scene& scene, const Camera& cam, const std::string& preset,
               const std::vector<std::string>& sets, const std::string& what) {
  Viewport vp(makeTechnique(preset, sets));
  vp.shownViews = vp.availableViews();
  FrameInput in;
  in.camera = cam;
  in.width = 160;
  in.height = 90;
  in.cut = true;
  h.renderer.render(in, {&vp});
  const test::Frame f = test::readFrame(h.renderer, vp, in.width, in.height);
  EXPECT_EQ(f.nonfinite(), 0) << what << " " << preset;
  // A degenerate camera (NaN view matrix) draws nothing and would pass every other check.
  long long covered = 0;
  for (size_t i = 3; i < f.position.size(); i += 4) covered += f.position[i] > 0.5f ? 1 : 0;
  EXPECT_GT(covered, in.width * in.height / 10) << what << " " << preset << ": the scene is not in the frame";
  for (size_t i = 0; i < f.visibility.size(); i += 2) {
    EXPECT_GE(f.visibility[i], 0.0f) << what << " " << preset;
    EXPECT_LE(f.visibility[i], 1.0f) << what << " " << preset;
    if (f.visibility[i] < 0.0f || f.visibility[i] > 1.0f) break;
  }
  return wrongPct(scene, f);
}

TEST(HardCases, EveryLayoutStaysFiniteAndDegradesToFocusing) {
  test::GlHarness h;
  for (const HardCase& hc : hardCases()) {
    Scene scene = loadScene("basic", defaultAssetsDir());
    Camera cam = scene.cameras.front();
    hc.setup(scene, cam);
    h.renderer.setScene(scene);
    const double focused = runCase(h, scene, cam, "standard", {"shadowmap.size=1024"}, hc.name);
    std::printf("%-50s focused %.2f %%", hc.name.c_str(), focused);  // one line per case
    for (const auto& [preset, sets] : std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"lispsm", {"shadowmap.size=1024"}},
             {"psm", {"shadowmap.size=1024"}},
             {"logpsm", {"shadowmap.size=1024"}},
             {"tsm", {"shadowmap.size=1024"}},
             {"face-partitioned", {"shadowmap.size=512"}},
             {"face-partitioned", {"shadowmap.size=362", "faces.depth_splits=2"}},
             {"cascaded", {"shadowmap.size=512"}},
             {"cascaded", {"shadowmap.size=512", "cascades.warp=lispsm"}},
             {"pixel-correct-lispsm", {"shadowmap.size=1024"}},
             {"alias-free", {}},
             {"virtual", {}},
             {"fitted-virtual", {}}}) {
      const double wrong = runCase(h, scene, cam, preset, sets, hc.name);
      const std::string variant = sets.size() < 2 ? "" : preset == "cascaded" ? "+warp" : "+z";
      std::printf(", %s%s %.2f %%", preset.c_str(), variant.c_str(), wrong);
      // Never garbage: within a point of the focused map's wrong pixels (one frame, 160x90).
      EXPECT_LE(wrong, focused + 1.0) << hc.name << " " << preset << variant;
      // The irregular z-buffer is exact: ties at most (techniques/irregular/README.md).
      if (preset == "alias-free") EXPECT_LE(wrong, 0.05) << hc.name;
    }
    std::printf("\n");
  }
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

}  // namespace
}  // namespace sl
