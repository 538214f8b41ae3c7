// The volumes pass (shaders/passes/volumes.frag): only scenes with volumes run it, and a pixel
// looking straight down through a constant slab gets the single-scattering colour computed by
// hand, lit through the technique's own visibility: `standard` lights the medium fully, `deep`
// by its own transmittance.
#include "tests/assets_dir.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <unistd.h>

namespace sl {
namespace {

using test::kAssets;

// The file name carries the pid: ctest runs these tests in parallel processes.
Scene volumesSceneFrom(const std::string& json) {
  return loadScene(test::writeTempFile("volumes_gl_" + std::to_string(::getpid()) + ".json", json), kAssets);
}

bool ran(const Renderer& r, const std::string& pass) {
  const auto& passes = r.stats().passes;
  return std::any_of(passes.begin(), passes.end(), [&](const PassTiming& p) { return p.name == pass; });
}

// Red channel at the centre pixel of the viewport's colour, in [0, 1] (display encoded).
float centreColour(test::GlHarness& h, const Scene& scene, const std::string& preset,
                   const std::vector<std::string>& sets) {
  h.renderer.setScene(scene);
  Viewport vp(makeTechnique(preset, sets));
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = in.height = 32;
  h.renderer.render(in, {&vp});
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  const std::vector<unsigned char> rgba = vp.colorTexture()->readRgba8();
  return rgba[4 * (16 * 32 + 16)] / 255.0f;
}

}  // namespace

using test::GlHarness;

TEST(VolumesPass, RunsOnlyInScenesWithVolumes) {
  GlHarness h;
  for (const std::string id : {"basic", "hair"}) {
    test::renderOnce(h, loadScene(id, kAssets), "deep", {"deep.size=64"}, 32, 18);
    EXPECT_FALSE(ran(h.renderer, "volumes[0]")) << id;
  }
  for (const std::string preset : {"standard", "deep", "pixel-correct"}) {
    test::renderOnce(h, loadScene("smoke", kAssets), preset, {}, 32, 18);
    EXPECT_TRUE(ran(h.renderer, "volumes[0]")) << preset;
  }
}

TEST(VolumesPass, SlabColourByHand) {
  GlHarness h;
  // Camera and light straight down; a slab 0.5 thick of sigma 2 (optical depth 1) over the ground.
  const std::string camera =
      R"("cameras":[{"position":[0.01,3,0.02],"target":[0,0,0],"fov_deg":20}],"light":{"type":"directional","direction":[0,-1,0]})";
  const std::string ground = R"({"objects":[{"name":"ground","shape":"plane","size":[4,4]}],)";
  const Scene bare = volumesSceneFrom(ground + camera + "}");
  const Scene slab = volumesSceneFrom(
      ground + R"("volumes":[{"shape":"box","center":[0,1,0],"size":[2,0.5,2],"extinction":2}],)" + camera + "}");
  // The ground fully lit: sqrt(albedo) (shading.glsl: sqrt(albedo * (0.18 + 0.82 * direct))).
  const float lit = centreColour(h, bare, "standard", {});
  ASSERT_GT(lit, 0.3f);
  const double t = std::exp(-1.0), albedo = 0.85;  // transmittance through the slab, medium albedo
  // standard: the medium lit fully, the ground too (volumes cast nothing in a depth map).
  // Medium radiance albedo * (1 - T); composited as sqrt(radiance / opacity) * opacity.
  const double standard = std::sqrt(albedo) * (1.0 - t) + t * lit;
  EXPECT_NEAR(centreColour(h, slab, "standard", {}), standard, 0.015);
  // deep: light at depth s in the slab is exp(-2 s), the ground gets exp(-1). The integral of
  // sigma exp(-sigma s) * albedo * (0.18 + 0.82 exp(-sigma s)) over the slab:
  const double light = albedo * (0.18 * (1.0 - t) + 0.82 * (1.0 - t * t) / 2.0);
  const double deep = std::sqrt(light / (1.0 - t)) * (1.0 - t) + t * lit * std::sqrt(0.18 + 0.82 * t);
  EXPECT_NEAR(centreColour(h, slab, "deep", {"deep.size=64"}), deep, 0.02);
  EXPECT_GT(standard - deep, 0.1) << "the two cases must be told apart";
}

}  // namespace sl
