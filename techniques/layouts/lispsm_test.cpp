// LiSPSM's free parameter (no GPU): the named endpoints of n, and no pop of the map when the
// view turns toward the light through the fallback to focusing.
#include "gl/shader_library.h"
#include "part/light_frame.h"
#include "layouts/layout_test_util.h"
#include "technique.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

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
  for (const char* snap : {"layout.snap=on", "layout.snap=off"}) {
    LightSpace inf = layoutFor("lispsm", scene, cam, {"lispsm.n=infinity", snap});
    LightSpace same = layoutFor("standard", scene, cam, {snap});
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) EXPECT_FLOAT_EQ(inf.primary().viewProj[c][r], same.primary().viewProj[c][r]) << snap;
  }
  LightSpace focused = layoutFor("standard", scene, cam, {"layout.snap=off"});
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
// Snapped, the fallback's texel size sits on a ladder (steps of 2^(1/8)), and a step of the ladder
// is a jump of the focused map itself: those steps are left out, nothing else is.
void expectNoPopWhileTurning(const char* snap) {
  Scene scene = loadScene("columns", defaultAssetsDir());
  const glm::vec3 L = glm::normalize(scene.light.direction);
  const glm::vec3 side = glm::normalize(glm::cross(L, glm::vec3(0, 1, 0)));
  Camera cam = scene.cameras.front();
  const bool snapped = std::string(snap) == "layout.snap=on";
  std::vector<float> steps;  // per step: the largest move of any receiver, in texels
  std::vector<bool> ladderStep;
  LightSpace prev, prevFocused;
  for (int k = 0; k <= 400; ++k) {
    const float gamma = 0.25f * (1.0f - k / 400.0f);  // sin(gamma) from 0.247 to 0
    cam.target = cam.position + std::cos(gamma) * L + std::sin(gamma) * side;
    LightSpace ls = layoutFor("lispsm", scene, cam, {"shadowmap.size=1024", snap});
    LightSpace focused = layoutFor("standard", scene, cam, {"shadowmap.size=1024", snap});
    if (k > 0) {
      float step = 0.0f;
      for (const auto& p : clipFrustumToBox(cameraView(cam), cameraProjection(cam, 16.0f / 9.0f), scene.boundsAt(0)))
        step = std::max(step, glm::length(texelPos(ls, p) - texelPos(prev, p)));
      steps.push_back(step);
      ladderStep.push_back(snapped && focused.primary().texelWorldSize != prevFocused.primary().texelWorldSize);
    }
    prev = ls;
    prevFocused = focused;
  }
  // A pop is a step far larger than its neighbours' (the map itself moves smoothly with the
  // view: near the viewer a strong warp moves texels fast, and that is no pop).
  float worst = 0.0f;
  int ladderSteps = 0;
  for (size_t i = 1; i + 1 < steps.size(); ++i) {
    if (ladderStep[i] && ++ladderSteps) continue;
    worst = std::max(worst, steps[i] - std::max(steps[i - 1], steps[i + 1]));
  }
  std::printf(
      "%s: largest step beyond its neighbours while turning: %.2f texels (largest step %.2f, %d ladder "
      "steps left out)\n",
      snap, worst, *std::max_element(steps.begin(), steps.end()), ladderSteps);
  EXPECT_LT(worst, 2.0f) << snap;
  EXPECT_LT(ladderSteps, 40) << snap;
}

TEST(Lispsm, TurningTowardTheLightDoesNotPopTheMap) {
  expectNoPopWhileTurning("layout.snap=off");
  expectNoPopWhileTurning("layout.snap=on");
}

// Looking along the light (the fallback) the map is the focused one, and with layout.snap its
// texel grid stays put in the world while the camera slides: between frames of the same texel
// size (a step of the ladder rescales the grid) a ground point keeps its position within its
// texel. Unsnapped, the grid slides with the camera.
TEST(Lispsm, TheFallbackKeepsTexelsStillUnderLayoutSnap) {
  Scene scene = loadScene("columns", defaultAssetsDir());
  const glm::vec3 L = glm::normalize(scene.light.direction);
  const Camera cam = scene.cameras.front();
  const glm::vec3 ground = cam.position + L * (cam.position.y / -L.y);  // under the view's centre
  // Snapped, only steps between frames of one texel size are compared.
  auto fractionDrift = [&](const char* snap, bool sameSizeOnly, int& comparedSteps) {
    float drift = 0.0f;
    LightSpace prev;
    comparedSteps = 0;
    for (int k = 0; k < 24; ++k) {
      Camera c = cam;
      c.position += glm::vec3(0.013f * k, 0.0f, 0.007f * k);
      c.target = c.position + L;  // sin(gamma) = 0: the fallback
      LightSpace ls = layoutFor("lispsm", scene, c, {"shadowmap.size=1024", snap});
      if (k > 0 && (!sameSizeOnly || ls.primary().texelWorldSize == prev.primary().texelWorldSize)) {
        const glm::vec2 d = glm::abs(glm::fract(texelPos(ls, ground) - texelPos(prev, ground) + 0.5f) - 0.5f);
        drift = std::max(drift, std::max(d.x, d.y));
        ++comparedSteps;
      }
      prev = ls;
    }
    return drift;
  };
  int snappedSteps = 0, unsnappedSteps = 0;
  const float snapped = fractionDrift("layout.snap=on", true, snappedSteps);
  const float unsnapped = fractionDrift("layout.snap=off", false, unsnappedSteps);
  std::printf("sub-texel drift of a ground point in the fallback: snapped %.4f (%d steps), unsnapped %.4f texels\n",
              snapped, snappedSteps, unsnapped);
  EXPECT_GE(snappedSteps, 12);
  EXPECT_LT(snapped, 0.01f);
  EXPECT_GT(unsnapped, 0.1f);
}

}  // namespace
}  // namespace sl
