// Face partitioning (no GPU): four views (eight with faces.depth_splits = 2), and every visible
// point lies in the map of the pyramid (and depth slice) the shader picks for it (by its camera
// clip position and view depth).
#include "gl/shader_library.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace sl {
namespace {

class FacePartitioned : public ::testing::TestWithParam<int> {};

TEST_P(FacePartitioned, EveryVisiblePointIsInItsFacesMap) {
  const int slices = GetParam();
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), t01(0.0f, 1.0f);
  for (const std::string id : {"basic", "columns", "dueling-frusta", "terrain"}) {
    Scene scene = loadScene(id, defaultAssetsDir());
    const Bounds b = scene.boundsAt(0);
    for (const Camera& cam : scene.cameras) {
      Technique t = makeTechnique("face-partitioned", {"faces.depth_splits=" + std::to_string(slices)});
      LayoutInput in;
      in.scene = &scene;
      in.cameraView = cameraView(cam);
      in.cameraProj = cameraProjection(cam, 16.0f / 9.0f);
      in.params = &t.params;
      const LightSpace ls = t.layout->compute(in);
      ASSERT_EQ(ls.views.size(), 4u * slices);
      if (slices == 2)
        for (int face = 0; face < 4; ++face) EXPECT_EQ(ls.views[face].splitFar, ls.views[face + 4].splitNear);
      const glm::mat4 inv = glm::inverse(in.cameraProj * in.cameraView);
      int tested = 0, missed = 0;
      for (int k = 0; k < 4000; ++k) {
        // Depths spread logarithmically between the near and far planes (NDC z of that depth).
        const float d = cam.nearPlane * std::pow(cam.farPlane / cam.nearPlane, t01(rng));
        const float n = cam.nearPlane, f = cam.farPlane, z = (f + n) / (f - n) - 2.0f * f * n / ((f - n) * d);
        const glm::vec2 xy(u(rng), u(rng));
        glm::vec4 h = inv * glm::vec4(xy, z, 1.0f);
        const glm::vec3 p = glm::vec3(h) / h.w;
        if (glm::any(glm::lessThan(p, b.min)) || glm::any(glm::greaterThan(p, b.max))) continue;
        int face = std::abs(xy.x) >= std::abs(xy.y) ? (xy.x >= 0 ? 0 : 1) : (xy.y >= 0 ? 2 : 3);
        if (slices == 2 && d >= ls.views[face].splitFar) face += 4;  // as face_partitioned.glsl picks
        const glm::vec4 c = ls.views[face].viewProj * glm::vec4(p, 1.0f);
        ++tested;
        missed += !(c.w > 0.0f && std::abs(c.x) <= c.w * 1.001f && std::abs(c.y) <= c.w * 1.001f);
      }
      EXPECT_GT(tested, 50) << id << "/" << cam.name;
      EXPECT_EQ(missed, 0) << id << "/" << cam.name << " of " << tested;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(DepthSplits, FacePartitioned, ::testing::Values(1, 2));

}  // namespace
}  // namespace sl
