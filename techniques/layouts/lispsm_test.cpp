// LiSPSM's free parameter (no GPU): the named endpoints of n, and no pop of the map when the
// view turns toward the light through the fallback to focusing.
#include "gl/shader_library.h"
#include "layouts/light_frame.h"
#include "layouts/layout_test_util.h"
#include "technique.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace sl {
namespace {

using test::layoutFor;

glm::vec2 texelPos(const LightSpace& ls, const glm::vec3& p) {
  glm::vec4 c = ls.primary().viewProj * glm::vec4(p, 1.0f);
  return (glm::vec2(c) / c.w * 0.5f + 0.5f) * static_cast<float>(ls.size);
}

TEST(Lispsm, InfiniteNIsTheFocusedMapAndZNearWarpsMoreThanNOpt) {
  Scene scene = loadScene("columns", defaultAssetsDir());
  const Camera& cam = scene.cameras.front();
  LightSpace inf = layoutFor("lispsm", scene, cam, {"lispsm.n=infinity"});
  LightSpace focused = layoutFor("standard", scene, cam, {"layout.snap=off"});
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_FLOAT_EQ(inf.primary().viewProj[c][r], focused.primary().viewProj[c][r]);
  // How much denser texels are near the viewer than far away on the ground (3 m vs 60 m): the
  // smaller n, the stronger the warp. z_n (PSM-like) > n_opt > focused (1).
  glm::vec3 dir = glm::normalize(glm::vec3(cam.target.x - cam.position.x, 0.0f, cam.target.z - cam.position.z));
  auto density = [&](const LightSpace& ls, float distance) {
    glm::vec3 p = glm::vec3(cam.position.x, 0.0f, cam.position.z) + dir * distance;
    return std::max(glm::length(texelPos(ls, p + glm::vec3(0.1f, 0, 0)) - texelPos(ls, p)),
                    glm::length(texelPos(ls, p + glm::vec3(0, 0, 0.1f)) - texelPos(ls, p)));
  };
  auto nearOverFar = [&](const LightSpace& ls) { return density(ls, 3.0f) / density(ls, 60.0f); };
  const float zn = nearOverFar(layoutFor("lispsm", scene, cam, {"lispsm.n=z_n"}));
  const float opt = nearOverFar(layoutFor("lispsm", scene, cam));
  const float flat = nearOverFar(focused);
  std::printf("near/far texel density: z_n %.1f, n_opt %.1f, focused %.2f\n", zn, opt, flat);
  EXPECT_GT(zn, opt * 1.2f);
  EXPECT_GT(opt, flat * 1.2f);
  EXPECT_NEAR(flat, 1.0f, 0.05f);
}

// The view turns toward the light in small steps, through the fallback at sin(gamma) = 0.05:
// between neighbouring steps no receiver may jump by more than a few texels. Before the smooth
// fallback the map switched from n_opt / 0.05 to focusing in one step (hundreds of texels).
TEST(Lispsm, TurningTowardTheLightDoesNotPopTheMap) {
  Scene scene = loadScene("columns", defaultAssetsDir());
  const glm::vec3 L = glm::normalize(scene.light.direction);
  const glm::vec3 side = glm::normalize(glm::cross(L, glm::vec3(0, 1, 0)));
  Camera cam = scene.cameras.front();
  std::vector<float> steps;  // per step: the largest move of any receiver, in texels
  LightSpace prev;
  for (int k = 0; k <= 400; ++k) {
    const float gamma = 0.25f * (1.0f - k / 400.0f);  // sin(gamma) from 0.247 to 0
    cam.target = cam.position + std::cos(gamma) * L + std::sin(gamma) * side;
    LightSpace ls = layoutFor("lispsm", scene, cam, {"shadowmap.size=1024"});
    if (k > 0) {
      float step = 0.0f;
      for (const auto& p : clipFrustumToBox(cameraView(cam), cameraProjection(cam, 16.0f / 9.0f), scene.boundsAt(0)))
        step = std::max(step, glm::length(texelPos(ls, p) - texelPos(prev, p)));
      steps.push_back(step);
    }
    prev = ls;
  }
  // A pop is a step far larger than its neighbours' (the map itself moves smoothly with the
  // view: near the viewer a strong warp moves texels fast, and that is no pop).
  float worst = 0.0f;
  for (size_t i = 1; i + 1 < steps.size(); ++i)
    worst = std::max(worst, steps[i] - std::max(steps[i - 1], steps[i + 1]));
  std::printf("largest step beyond its neighbours while turning: %.2f texels (largest step %.2f)\n", worst,
              *std::max_element(steps.begin(), steps.end()));
  EXPECT_LT(worst, 2.0f);
}

}  // namespace
}  // namespace sl
