// Trapezoidal shadow maps (no GPU): the trapezoid covers every visible receiver, the focus line
// lands at tsm.focus_share of the map, and texels are denser near the viewer than with focusing.
#include "gl/shader_library.h"
#include "part/light_frame.h"
#include "layouts/layout_test_util.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sl {
namespace {

using test::layoutFor;

glm::vec3 tsmNdc(const LightSpace& ls, const glm::vec3& p) {
  glm::vec4 c = ls.primary().viewProj * glm::vec4(p, 1.0f);
  EXPECT_GT(c.w, 0.0f);
  return glm::vec3(c) / c.w;
}

TEST(Tsm, TrapezoidCoversEveryVisibleReceiverAndItsCasters) {
  for (const std::string id : {"basic", "columns", "dueling-frusta", "terrain", "thin-casters", "grazing"}) {
    Scene scene = loadScene(id, defaultAssetsDir());
    for (const Camera& cam : scene.cameras) {
      LightSpace ls = layoutFor("tsm", scene, cam);
      const LightView& v = ls.primary();
      const glm::vec3 L = glm::normalize(scene.light.direction);
      for (const auto& p : clipFrustumToBox(cameraView(cam), cameraProjection(cam, 16.0f / 9.0f), scene.boundsAt(0))) {
        glm::vec3 q = tsmNdc(ls, p);
        EXPECT_LE(std::abs(q.x), 1.0001f) << id << "/" << cam.name;
        EXPECT_LE(std::abs(q.y), 1.0001f) << id << "/" << cam.name;
        EXPECT_LE(std::abs(q.z), 1.0001f) << id << "/" << cam.name;
        // A caster toward the light on the same ray must not be clipped either.
        const float lightDepth = -(v.view * glm::vec4(p, 1.0f)).z;
        glm::vec3 caster = tsmNdc(ls, p - L * (lightDepth - v.nearPlane) * 0.999f);
        EXPECT_LE(std::abs(caster.z), 1.0001f) << id << "/" << cam.name;
      }
    }
  }
}

// A mirrored map turns front faces into back faces (the shadow pass culls by winding).
TEST(Tsm, KeepsTheLightPlanesOrientation) {
  for (const std::string id : {"basic", "columns", "terrain"}) {
    Scene scene = loadScene(id, defaultAssetsDir());
    for (const Camera& cam : scene.cameras) {
      LightSpace ls = layoutFor("tsm", scene, cam);
      const glm::mat4 inv = glm::inverse(ls.primary().view);
      const glm::vec3 o = glm::vec3(inv * glm::vec4(0, 0, -50, 1)), x = glm::vec3(inv * glm::vec4(0.01f, 0, -50, 1)),
                      y = glm::vec3(inv * glm::vec4(0, 0.01f, -50, 1));
      auto ndc2 = [&](const glm::vec3& p) {
        glm::vec4 c = ls.primary().viewProj * glm::vec4(p, 1.0f);
        return glm::vec2(c) / c.w;
      };
      const glm::vec2 dx = ndc2(x) - ndc2(o), dy = ndc2(y) - ndc2(o);
      EXPECT_GT(dx.x * dy.y - dx.y * dy.x, 0.0f) << id << "/" << cam.name;
    }
  }
}

TEST(Tsm, FocusLineLandsAtItsShareOfTheMapAndNearTexelsAreDenser) {
  Scene scene = loadScene("columns", defaultAssetsDir());
  const Camera& cam = scene.cameras.front();
  for (float share : {0.6f, 0.8f, 0.9f}) {
    LightSpace ls = layoutFor("tsm", scene, cam, {"tsm.focus_share=" + std::to_string(share)});
    // The visible depth range's near end is the near plane here (the ground starts at the camera).
    auto receivers = clipFrustumToBox(cameraView(cam), cameraProjection(cam, 16.0f / 9.0f), scene.boundsAt(0));
    const glm::vec3 dir = glm::normalize(cam.target - cam.position);
    float zMin = 1e30f, zMax = -1e30f;
    for (const auto& p : receivers) {
      zMin = std::min(zMin, glm::dot(p - cam.position, dir));
      zMax = std::max(zMax, glm::dot(p - cam.position, dir));
    }
    const glm::vec3 nearC = cam.position + dir * std::max(zMin, 0.0f), farC = cam.position + dir * zMax;
    const glm::vec3 focus = cam.position + dir * (std::max(zMin, 0.0f) + 0.3f * (zMax - std::max(zMin, 0.0f)));
    // Along the centre line the map runs from the top edge (near) to the base (far): the focus
    // point's share of that run.
    const glm::vec2 a = glm::vec2(tsmNdc(ls, nearC)), b = glm::vec2(tsmNdc(ls, farC)), f = glm::vec2(tsmNdc(ls, focus));
    EXPECT_NEAR((f.y + 1.0f) * 0.5f, share, 0.03f) << share;
    EXPECT_LT(a.y, f.y);
    EXPECT_LT(f.y, b.y);
  }
  LightSpace trap = layoutFor("tsm", scene, cam), focused = layoutFor("standard", scene, cam);
  const glm::vec3 dir = glm::normalize(glm::vec3(cam.target.x - cam.position.x, 0.0f, cam.target.z - cam.position.z));
  const glm::vec3 p = glm::vec3(cam.position.x, 0.0f, cam.position.z) + dir * 3.0f;
  auto density = [&](const LightSpace& ls) {
    return glm::length(glm::vec2(tsmNdc(ls, p + glm::vec3(0.1f, 0, 0.1f))) - glm::vec2(tsmNdc(ls, p)));
  };
  EXPECT_GT(density(trap), 2.0f * density(focused));
}

}  // namespace
}  // namespace sl
