// Perspective shadow maps (no GPU): every visible receiver and the casters toward the light are
// in the map, the map keeps the light plane's orientation (the shadow pass culls by winding), and
// pushing the near plane trades warp for an even depth distribution.
#include "gl/shader_library.h"
#include "part/light_frame.h"
#include "layouts/layout_test_util.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sl {
namespace {

LightSpace layoutFor(const Scene& scene, const Camera& cam, std::vector<std::string> overrides = {}) {
  return test::layoutFor("psm", scene, cam, std::move(overrides));
}

glm::vec3 psmNdc(const LightSpace& ls, const glm::vec3& p) {
  glm::vec4 c = ls.primary().viewProj * glm::vec4(p, 1.0f);
  EXPECT_GT(c.w, 0.0f);
  return glm::vec3(c) / c.w;
}

TEST(Psm, CoversEveryVisibleReceiverAndKeepsTheOrientation) {
  for (const std::string id : {"basic", "columns", "dueling-frusta", "terrain", "thin-casters", "grazing"}) {
    Scene scene = loadScene(id, defaultAssetsDir());
    const glm::vec3 L = glm::normalize(scene.light.direction);
    for (const Camera& cam : scene.cameras) {
      LightSpace ls = layoutFor(scene, cam);
      for (const auto& p : clipFrustumToBox(cameraView(cam), cameraProjection(cam, 16.0f / 9.0f), scene.boundsAt(0))) {
        glm::vec3 q = psmNdc(ls, p);
        EXPECT_LE(std::abs(q.x), 1.001f) << id << "/" << cam.name;
        EXPECT_LE(std::abs(q.y), 1.001f) << id << "/" << cam.name;
        EXPECT_LE(std::abs(q.z), 1.001f) << id << "/" << cam.name;
      }
      // Seen from the light, a counter-clockwise triangle stays counter-clockwise in the map.
      const glm::vec3 side =
          glm::normalize(glm::cross(L, std::abs(L.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
      const glm::vec3 up = glm::cross(side, L);
      const glm::vec3 o = scene.boundsAt(0).center();
      const glm::vec2 a = glm::vec2(psmNdc(ls, o)), b = glm::vec2(psmNdc(ls, o + side * 0.01f)),
                      c = glm::vec2(psmNdc(ls, o + up * 0.01f));
      const glm::mat4 lv = lightViewMatrix(scene.light, 0.0f);
      const glm::vec2 la = glm::vec2(lv * glm::vec4(o, 1)), lb = glm::vec2(lv * glm::vec4(o + side * 0.01f, 1)),
                      lc = glm::vec2(lv * glm::vec4(o + up * 0.01f, 1));
      auto cross = [](glm::vec2 u, glm::vec2 v) { return u.x * v.y - u.y * v.x; };
      EXPECT_GT(cross(b - a, c - a) * cross(lb - la, lc - la), 0.0f) << id << "/" << cam.name;
    }
  }
}

}  // namespace
}  // namespace sl
