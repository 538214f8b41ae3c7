// Geometry of the layouts (no GPU): focusing covers what it must, snapping moves by texels.
#include "gl/shader_library.h"
#include "part/light_frame.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sl {

static LightSpace computeFor(const std::string& preset, const Scene& scene, const Camera& cam,
                             std::vector<std::string> overrides = {}) {
  Technique t = makeTechnique(preset, overrides);
  LayoutInput in;
  in.scene = &scene;
  in.cameraView = cameraView(cam);
  in.cameraProj = cameraProjection(cam, 16.0f / 9.0f);
  in.params = &t.params;
  return t.layout->compute(in);
}

static float depth01(const LightSpace& ls, const glm::vec3& p) {
  return (-(ls.primary().view * glm::vec4(p, 1.0f)).z - ls.primary().nearPlane) /
         (ls.primary().farPlane - ls.primary().nearPlane);
}

TEST(Layout, FocusedCoversEveryVisibleReceiverAndTheCastersTowardTheLight) {
  for (const std::string id : {"basic", "columns", "dueling-frusta", "terrain", "thin-casters"}) {
    Scene scene = loadScene(id, defaultAssetsDir());
    for (const Camera& cam : scene.cameras) {
      LightSpace ls = computeFor("standard", scene, cam);
      Bounds b = scene.boundsAt(0);
      auto receivers = clipFrustumToBox(cameraView(cam), cameraProjection(cam, 16.0f / 9.0f), b);
      ASSERT_FALSE(receivers.empty()) << id << "/" << cam.name;
      for (const auto& p : receivers) {
        glm::vec4 c = ls.primary().viewProj * glm::vec4(p, 1.0f);
        EXPECT_LE(std::abs(c.x / c.w), 1.0001f) << id << "/" << cam.name;
        EXPECT_LE(std::abs(c.y / c.w), 1.0001f) << id << "/" << cam.name;
        EXPECT_GE(depth01(ls, p), 0.0f);
        EXPECT_LE(depth01(ls, p), 1.0f);
      }
      // Any caster between a receiver and the light lies within the scene bounds, toward the
      // light: its depth must not be clipped by the near plane.
      for (const auto& p : boxCorners(b)) EXPECT_GE(depth01(ls, p), 0.0f) << id << "/" << cam.name;
      // Focusing is worth it: the focused window is no larger than the uniform one.
      LightSpace u = computeFor("uniform", scene, cam);
      EXPECT_LE(ls.primary().texelWorldSize, u.primary().texelWorldSize * 1.2f) << id << "/" << cam.name;
    }
  }
}

TEST(Layout, LispsmCoversEveryVisibleReceiverAndTheirCasters) {
  for (const std::string id : {"basic", "columns", "dueling-frusta", "terrain", "thin-casters"}) {
    Scene scene = loadScene(id, defaultAssetsDir());
    for (const Camera& cam : scene.cameras) {
      LightSpace ls = computeFor("lispsm", scene, cam);
      Bounds b = scene.boundsAt(0);
      auto receivers = clipFrustumToBox(cameraView(cam), cameraProjection(cam, 16.0f / 9.0f), b);
      for (const auto& p : receivers) {
        glm::vec4 c = ls.primary().viewProj * glm::vec4(p, 1.0f);
        ASSERT_GT(c.w, 0.0f) << id << "/" << cam.name;
        EXPECT_LE(std::abs(c.x / c.w), 1.0001f) << id << "/" << cam.name;
        EXPECT_LE(std::abs(c.y / c.w), 1.0001f) << id << "/" << cam.name;
        EXPECT_LE(std::abs(c.z / c.w), 1.0001f) << id << "/" << cam.name;  // not clipped
        EXPECT_GE(depth01(ls, p), 0.0f);
        EXPECT_LE(depth01(ls, p), 1.0f);
      }
      for (const auto& p : boxCorners(b)) EXPECT_GE(depth01(ls, p), 0.0f) << id << "/" << cam.name;
    }
  }
}

// The point of the warp: near the viewer a texel covers less ground than with focusing alone.
TEST(Layout, LispsmPutsMoreTexelsNearTheViewer) {
  Scene scene = loadScene("columns", defaultAssetsDir());
  const Camera& cam = scene.cameras.front();
  LightSpace focused = computeFor("standard", scene, cam), warped = computeFor("lispsm", scene, cam);
  // A ground point just in front of the camera, and one texel-sized step on the ground there.
  glm::vec3 viewDir = glm::normalize(cam.target - cam.position);
  glm::vec3 p = cam.position + glm::normalize(glm::vec3(viewDir.x, 0.0f, viewDir.z)) * 3.0f;
  p.y = 0.0f;
  auto texelsPerMetre = [&](const LightSpace& ls) {
    glm::vec4 a = ls.primary().viewProj * glm::vec4(p, 1.0f),
              c = ls.primary().viewProj * glm::vec4(p + glm::vec3(0.0f, 0.0f, 0.1f), 1.0f);
    glm::vec4 d = ls.primary().viewProj * glm::vec4(p + glm::vec3(0.1f, 0.0f, 0.0f), 1.0f);
    glm::vec2 pa = glm::vec2(a) / a.w;
    return 0.5f * ls.size / 0.1f * std::max(glm::length(glm::vec2(c) / c.w - pa), glm::length(glm::vec2(d) / d.w - pa));
  };
  EXPECT_GT(texelsPerMetre(warped), 3.0f * texelsPerMetre(focused));
}

TEST(Layout, FocusedIsSmallerThanUniformOnALargeScene) {
  Scene scene = loadScene("terrain", defaultAssetsDir());
  Camera cam = scene.cameras.front();
  cam.position = glm::vec3(10, 6, 10);  // looking down at a patch of ground near the viewer
  cam.target = glm::vec3(0, 0, 0);
  cam.farPlane = 60;
  EXPECT_LT(computeFor("standard", scene, cam).primary().texelWorldSize,
            computeFor("uniform", scene, cam).primary().texelWorldSize * 0.5f);
}

TEST(Layout, SnappingMovesTheLightFrustumByWholeTexels) {
  Scene scene = loadScene("basic", defaultAssetsDir());
  Camera a = scene.cameras.front();
  int whole = 0, fractional = 0;
  for (int k = 1; k <= 20; ++k) {
    Camera b = a;
    glm::vec3 shift(0.013f * k, 0.0f, -0.007f * k);  // a slow, small camera move
    b.position += shift;
    b.target += shift;
    LightSpace la = computeFor("standard", scene, a, {"layout.snap=on"});
    LightSpace lb = computeFor("standard", scene, b, {"layout.snap=on"});
    if (la.primary().texelWorldSize != lb.primary().texelWorldSize) continue;  // the ladder stepped: a new grid
    glm::vec2 texels = (lb.primary().windowMin - la.primary().windowMin) / la.primary().texelWorldSize;
    EXPECT_NEAR(texels.x, std::round(texels.x), 1e-2f);
    EXPECT_NEAR(texels.y, std::round(texels.y), 1e-2f);
    ++whole;
    LightSpace ua = computeFor("standard", scene, a, {"layout.snap=off"});
    LightSpace ub = computeFor("standard", scene, b, {"layout.snap=off"});
    glm::vec2 t = (ub.primary().windowMin - ua.primary().windowMin) / ua.primary().texelWorldSize;
    if (std::abs(t.x - std::round(t.x)) > 0.05f || std::abs(t.y - std::round(t.y)) > 0.05f) ++fractional;
  }
  EXPECT_GE(whole, 10);      // the texel size stays put for most small moves
  EXPECT_GE(fractional, 5);  // and without snapping the grid slides by fractions of texels
}

TEST(Layout, SpotLightGetsAPerspectiveMap) {
  Scene scene = loadScene("basic", defaultAssetsDir());
  scene.light.type = Light::Type::Spot;
  scene.light.position = glm::vec3(4, 6, 3);
  scene.light.direction = glm::normalize(glm::vec3(-4, -6, -3));
  scene.light.fovDeg = 70;
  LightSpace ls = computeFor("standard", scene, scene.cameras.front());
  EXPECT_TRUE(ls.primary().perspective);
  EXPECT_GT(ls.primary().nearPlane, 0.0f);
  for (const auto& p : clipFrustumToBox(cameraView(scene.cameras.front()),
                                        cameraProjection(scene.cameras.front(), 16.0f / 9.0f), scene.boundsAt(0))) {
    // Only points inside the cone (a square map covers the cone's square around it) matter.
    float halfTan = std::tan(glm::radians(scene.light.fovDeg) * 0.5f);
    glm::vec3 q = glm::vec3(ls.primary().view * glm::vec4(p, 1.0f));
    if (-q.z <= 0.0f || std::abs(q.x / -q.z) > halfTan || std::abs(q.y / -q.z) > halfTan) continue;
    glm::vec4 c = ls.primary().viewProj * glm::vec4(p, 1.0f);
    ASSERT_GT(c.w, 0.0f);
    EXPECT_LE(std::abs(c.x / c.w), 1.0001f);
    EXPECT_LE(std::abs(c.y / c.w), 1.0001f);
  }
}

}  // namespace sl
