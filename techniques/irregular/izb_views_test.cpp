// Which light views the irregular z-buffer can list samples in under a sun (no GPU): a view
// whose matrix sends a sample's whole ray to the sun onto one point of its grid. By hand on
// small matrices, then on the views the layouts compute for cameras turned all around.
#include "gl/shader_library.h"
#include "irregular/izb_state.h"
#include "technique.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace sl {
namespace {

// How far from depth alone a matrix sends the direction to the sun, relative to its scale.
float offDepth(const glm::mat4& m, const glm::vec3& toLight) {
  const glm::vec4 image = m * glm::vec4(toLight, 0.0f);
  float scale = 0.0f;
  for (int column = 0; column < 3; ++column) scale = std::max(scale, glm::length(m[column]));
  return std::max({std::abs(image.x), std::abs(image.y), std::abs(image.w)}) / scale;
}

TEST(IzbViews, SunGridsAreOrthographicOrWarpedAcrossTheLight) {
  const glm::vec3 toLight = glm::normalize(glm::vec3(0.3f, 1.0f, -0.2f));
  const glm::mat4 lightView = glm::lookAt(glm::vec3(0.0f), -toLight, glm::vec3(0.0f, 0.0f, 1.0f));
  glm::mat4 grid;
  // Orthographic along the light, at a small and a large scale: its own matrix, to rounding.
  for (float half : {0.01f, 1e4f}) {
    const glm::mat4 ortho = glm::ortho(-half, half, -half, half, -half, half) * lightView;
    ASSERT_TRUE(sunGridMatrix(ortho, toLight, grid)) << half;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) EXPECT_NEAR(grid[c][r], ortho[c][r], 1e-5f * std::abs(ortho[0][0])) << half;
  }
  // A perspective whose axis is the light view's y (LiSPSM's): w = y, which a ray along z keeps.
  glm::mat4 across(0.0f);
  across[0][0] = 1.0f, across[1][1] = 2.0f, across[3][1] = -3.0f, across[2][2] = 1.0f, across[1][3] = 1.0f;
  EXPECT_TRUE(sunGridMatrix(across * lightView, toLight, grid));
  // The same turned by 1e-5 rad, as rounding might: accepted, and the grid sends the ray to depth.
  const glm::mat4 nudged = across * glm::rotate(glm::mat4(1.0f), 1e-5f, glm::vec3(1, 0, 0)) * lightView;
  EXPECT_GT(offDepth(nudged, toLight), 1e-6f);
  ASSERT_TRUE(sunGridMatrix(nudged, toLight, grid));
  EXPECT_LT(offDepth(grid, toLight), 1e-7f);
  // A perspective looking along the light (the sun's rays converge on its image's centre) and
  // the warp tilted by 0.01 rad toward it: a ray's image moves, not a grid of the view.
  EXPECT_FALSE(sunGridMatrix(glm::perspective(1.0f, 1.0f, 0.1f, 10.0f) * lightView, toLight, grid));
  const glm::mat4 tilted = glm::rotate(glm::mat4(1.0f), 0.01f, glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_FALSE(sunGridMatrix(across * tilted * lightView, toLight, grid));
}

// The views a preset's layout computes for a camera on a circle around the scene's target,
// looking at it from three heights: how many pass, of how many.
std::pair<int, int> passingViews(const std::string& sceneId, const std::string& layout) {
  const Scene scene = loadScene(sceneId, defaultAssetsDir());
  Technique t = makeTechnique("alias-free", {"technique.layout=" + layout});
  const Camera base = scene.cameras.front();
  int passed = 0, total = 0;
  for (int yaw = 0; yaw < 360; yaw += 20)
    for (float height : {0.3f, 2.0f, 15.0f}) {
      Camera cam = base;
      const glm::vec3 offset = base.position - base.target;
      const float radius = glm::length(glm::vec2(offset.x, offset.z));
      const float a = glm::radians(static_cast<float>(yaw));
      cam.position = base.target + glm::vec3(radius * std::cos(a), height, radius * std::sin(a));
      LayoutInput in;
      in.scene = &scene;
      in.cameraView = cameraView(cam);
      in.cameraProj = cameraProjection(cam, 16.0f / 9.0f);
      in.params = &t.params;
      for (const LightView& v : t.layout->compute(in).views) {
        ++total;
        glm::mat4 grid;
        if (v.projection != LightView::Projection::Matrix || !sunGridMatrix(v.viewProj, -scene.light.direction, grid))
          continue;
        ++passed;
        EXPECT_LT(offDepth(grid, -scene.light.direction), 1e-7f) << sceneId << " " << layout << " yaw " << yaw;
      }
    }
  return {passed, total};
}

TEST(IzbViews, EveryFocusedLispsmTsmAndCascadeViewGivesAGrid) {
  for (const char* sceneId : {"basic", "columns", "terrain"}) {
    for (const char* layout : {"focused", "lispsm", "tsm", "cascaded"}) {
      const auto [passed, total] = passingViews(sceneId, layout);
      EXPECT_EQ(passed, total) << sceneId << " " << layout;
      EXPECT_GE(total, 54) << sceneId << " " << layout;
    }
  }
}

}  // namespace
}  // namespace sl
