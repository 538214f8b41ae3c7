// Faces kept between frames (face_cache.h) on the GPU: a still camera over a static scene keeps
// every face, an object moving under some faces redraws those alone, and either way the picture
// is exactly the one drawing every face gives.
#include "tests/assets_dir.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <unistd.h>

namespace sl {
namespace {

// "cube: N of M faces drawn, K kept from an earlier frame" -> {N, K}.
std::pair<int, int> drawnAndKept(const std::string& status) {
  int needed = -1, total = -1, kept = 0;
  std::sscanf(status.c_str(), "cube: %d of %d faces drawn, %d kept", &needed, &total, &kept);
  return {needed, kept};
}

// Renders the viewports through the same frames (times; the first a cut) and returns the largest
// visibility difference between the two.
float largestDifference(test::GlHarness& h, FrameInput in, Viewport& a, Viewport& b, const std::vector<double>& times) {
  for (size_t i = 0; i < times.size(); ++i) {
    in.time = times[i];
    in.cut = i == 0;
    h.renderer.render(in, {&a, &b});
  }
  const std::vector<float> va = a.visibilityTexture()->readFloats(2), vb = b.visibilityTexture()->readFloats(2);
  float worst = 0;
  for (size_t i = 0; i < va.size(); i += 2) worst = std::max(worst, std::abs(va[i] - vb[i]));
  return worst;
}

TEST(FaceCacheGl, AStillCameraKeepsEveryFaceAndThePictureStaysExact) {
  test::GlHarness h;
  const Scene scene = loadScene("street", test::kAssets);
  h.renderer.setScene(scene);
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 160;
  in.height = 90;
  for (const char* preset : {"cube", "cube-pcf"}) {
    Viewport kept(makeTechnique(preset, {"shadowmap.size=256"}));
    Viewport drawn(makeTechnique(preset, {"shadowmap.size=256", "point.keep_faces=0"}));
    EXPECT_EQ(largestDifference(h, in, kept, drawn, {0.0, 0.0, 0.0, 0.0}), 0.0f) << preset;
    const auto [needed, keptFaces] = drawnAndKept(kept.layout->status());
    EXPECT_GT(needed, 0) << kept.layout->status();
    EXPECT_EQ(keptFaces, needed) << kept.layout->status();
    EXPECT_EQ(drawnAndKept(drawn.layout->status()).second, 0) << drawn.layout->status();
  }
  // A moment map does not keep its layers (its filter passes rewrite them): nothing kept.
  Viewport vsm(makeTechnique("vsm", {"technique.layout=cube", "shadowmap.size=256"}));
  for (int f = 0; f < 3; ++f) h.renderer.render(in, {&vsm});
  EXPECT_EQ(vsm.layout->status().find("kept"), std::string::npos) << vsm.layout->status();
}

// A box oscillating along z beside the lamp: the faces whose frusta it is in (where it is or was)
// are drawn again, the others kept, and the visibility is exactly that of drawing every face.
TEST(FaceCacheGl, AMovingObjectRedrawsOnlyTheFacesItIsIn) {
  test::GlHarness h;
  const Scene scene = loadScene(test::writeTempFile("face_cache_moving_" + std::to_string(::getpid()) + ".json", R"({
    "objects":[{"name":"ground","shape":"plane","size":[30,30]},
      {"name":"still","shape":"box","size":[1,1,1],"transform":{"translate":[-3,0.5,0]}},
      {"name":"moving","shape":"box","size":[0.6,0.6,0.6],"transform":{"translate":[3,1.5,0]},
       "motion":{"type":"oscillate","vector":[0,0,1],"period":4}}],
    "light":{"type":"point","position":[0,3,0],"range":30},
    "cameras":[{"name":"top","position":[0,14,9],"target":[0,0,0],"fov_deg":70}]})"),
                                test::kAssets);
  h.renderer.setScene(scene);
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 160;
  in.height = 90;
  Viewport kept(makeTechnique("cube", {"shadowmap.size=256"}));
  Viewport drawn(makeTechnique("cube", {"shadowmap.size=256", "point.keep_faces=0"}));
  EXPECT_LE(largestDifference(h, in, kept, drawn, {0.0, 0.0, 0.0, 0.5}), 0.0f);
  const auto [needed, keptFaces] = drawnAndKept(kept.layout->status());
  EXPECT_GT(keptFaces, 0) << kept.layout->status();
  EXPECT_LT(keptFaces, needed) << kept.layout->status();
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

}  // namespace
}  // namespace sl
