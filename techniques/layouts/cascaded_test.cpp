// Geometry of the cascaded layout (no GPU): the splits follow their formulas, every visible
// point is inside the split that serves it (and the blend band inside the next one too), and
// snapped splits keep their texel grid still while the camera turns and moves.
#include "gl/shader_library.h"
#include "layouts/cascade_fit.h"
#include "part/light_frame.h"
#include "layouts/layout_test_util.h"
#include "technique.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace sl {
namespace {

LightSpace cascadesFor(const Scene& scene, const Camera& cam, std::vector<std::string> overrides = {}) {
  return test::layoutFor("cascaded", scene, cam, std::move(overrides));
}

// Normalized window position and stored depth of p in view v.
glm::vec3 inView(const LightView& v, const glm::vec3& p) {
  glm::vec4 c = v.viewProj * glm::vec4(p, 1.0f);
  float depth = (-(v.view * glm::vec4(p, 1.0f)).z - v.nearPlane) / (v.farPlane - v.nearPlane);
  return glm::vec3(glm::vec2(c) / c.w, depth);
}

bool covers(const LightView& v, const glm::vec3& p) {
  glm::vec3 q = inView(v, p);
  return std::abs(q.x) <= 1.0001f && std::abs(q.y) <= 1.0001f && q.z >= -1e-4f && q.z <= 1.0001f;
}

TEST(Cascaded, SplitSchemesFollowTheirFormulas) {
  const float n = 0.1f, f = 1000.0f;
  auto u = cascadeSplits(4, SplitScheme::Uniform, 0.5f, n, f);
  auto l = cascadeSplits(4, SplitScheme::Logarithmic, 0.5f, n, f);
  auto p = cascadeSplits(4, SplitScheme::Practical, 0.5f, n, f);
  ASSERT_EQ(u.size(), 5u);
  for (auto* s : {&u, &l, &p}) {
    EXPECT_FLOAT_EQ(s->front(), n);
    EXPECT_FLOAT_EQ(s->back(), f);
    for (size_t i = 1; i < s->size(); ++i) EXPECT_GT((*s)[i], (*s)[i - 1]);
  }
  for (size_t i = 1; i + 1 < u.size(); ++i) {
    EXPECT_NEAR(u[i + 1] - u[i], u[i] - u[i - 1], 1e-2f);                    // equal steps
    EXPECT_NEAR(l[i + 1] / l[i], l[i] / l[i - 1], 1e-3f * l[i] / l[i - 1]);  // equal ratios
    EXPECT_NEAR(p[i], 0.5f * (u[i] + l[i]), 1e-3f * p[i]);
  }
}

TEST(Cascaded, EveryVisiblePointIsInItsSplitAndBlendBandsInTheNextToo) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (const std::string id : {"basic", "columns", "dueling-frusta", "terrain", "thin-casters"}) {
    Scene scene = loadScene(id, defaultAssetsDir());
    const Bounds b = scene.boundsAt(0);
    for (const Camera& cam : scene.cameras) {
      for (const std::string scheme : {"uniform", "logarithmic", "practical"}) {
        LightSpace ls = cascadesFor(scene, cam, {"cascades.scheme=" + scheme});
        ASSERT_EQ(ls.views.size(), 4u);
        const glm::mat4 view = cameraView(cam), toWorld = glm::inverse(view);
        const float tx = std::tan(glm::radians(cam.fovDeg) * 0.5f) * 16.0f / 9.0f,
                    ty = std::tan(glm::radians(cam.fovDeg) * 0.5f);
        std::uniform_real_distribution<float> t01(0.0f, 1.0f);
        int tested = 0;
        for (int k = 0; k < 4000; ++k) {
          // Depths spread both logarithmically (near splits) and uniformly (far splits).
          const float u = t01(rng);
          const float d = k % 2 ? cam.nearPlane * std::pow(cam.farPlane / cam.nearPlane, u)
                                : cam.nearPlane + (cam.farPlane - cam.nearPlane) * u;
          glm::vec3 p = glm::vec3(toWorld * glm::vec4(unit(rng) * tx * d, unit(rng) * ty * d, -d, 1.0f));
          if (glm::any(glm::lessThan(p, b.min)) || glm::any(glm::greaterThan(p, b.max))) continue;
          float depth = -(view * glm::vec4(p, 1.0f)).z;
          size_t v = 0;
          while (v + 1 < ls.views.size() && depth >= ls.views[v].splitFar) ++v;
          ASSERT_TRUE(covers(ls.views[v], p)) << id << "/" << cam.name << " " << scheme << " split " << v;
          if (v + 1 < ls.views.size() && depth > ls.views[v].splitFar - ls.views[v].blendBand)
            EXPECT_TRUE(covers(ls.views[v + 1], p)) << id << "/" << cam.name << " band of split " << v;
          ++tested;
        }
        EXPECT_GT(tested, 50) << id << "/" << cam.name;
      }
    }
  }
}

TEST(Cascaded, SplitsAreOrderedAndFartherSplitsHaveCoarserTexels) {
  Scene scene = loadScene("terrain", defaultAssetsDir());
  for (int count = 1; count <= kMaxLightViews; ++count) {
    LightSpace ls = cascadesFor(scene, scene.cameras.front(), {"cascades.count=" + std::to_string(count)});
    ASSERT_EQ(static_cast<int>(ls.views.size()), count);
    EXPECT_EQ(ls.size, 2048);
    EXPECT_FLOAT_EQ(ls.views.front().splitNear, scene.cameras.front().nearPlane);
    for (int i = 1; i < count; ++i) {
      EXPECT_FLOAT_EQ(ls.views[i].splitNear, ls.views[i - 1].splitFar);
      EXPECT_GT(ls.views[i].texelWorldSize, ls.views[i - 1].texelWorldSize);
      EXPECT_GT(ls.views[i - 1].blendBand, 0.0f);
      EXPECT_LT(ls.views[i - 1].blendBand, ls.views[i - 1].splitFar - ls.views[i - 1].splitNear);
    }
    EXPECT_EQ(ls.views.back().blendBand, 0.0f);
  }
}

// Texel grid offset between two frames of one split, in texels: whole numbers when snapped.
glm::vec2 gridShift(const LightView& a, const LightView& b) { return (b.windowMin - a.windowMin) / a.texelWorldSize; }

TEST(Cascaded, SnappedSplitsKeepTheirTexelsStillWhileTheCameraTurnsAndMoves) {
  Scene scene = loadScene("terrain", defaultAssetsDir());
  const Camera base = scene.cameras.front();
  int snappedChecks = 0, unsnappedFractional = 0;
  for (int k = 1; k <= 24; ++k) {
    Camera c = base;
    const float yaw = 0.0021f * k;  // a slow turn, then a slow walk
    glm::vec3 dir =
        glm::vec3(glm::rotate(glm::mat4(1.0f), yaw, glm::vec3(0, 1, 0)) * glm::vec4(base.target - base.position, 0));
    c.position += glm::vec3(0.011f * k, 0.0f, -0.017f * k) * float(k > 12);
    c.target = c.position + dir;
    LightSpace a = cascadesFor(scene, base), b = cascadesFor(scene, c);
    LightSpace ua = cascadesFor(scene, base, {"layout.snap=off"}), ub = cascadesFor(scene, c, {"layout.snap=off"});
    for (size_t i = 0; i < a.views.size(); ++i) {
      // The bounding sphere does not depend on the view direction: the texel size stays put.
      EXPECT_EQ(a.views[i].texelWorldSize, b.views[i].texelWorldSize) << "split " << i << " step " << k;
      glm::vec2 t = gridShift(a.views[i], b.views[i]);
      EXPECT_NEAR(t.x, std::round(t.x), 2e-2f) << "split " << i << " step " << k;
      EXPECT_NEAR(t.y, std::round(t.y), 2e-2f) << "split " << i << " step " << k;
      ++snappedChecks;
      glm::vec2 u = gridShift(ua.views[i], ub.views[i]);
      if (std::abs(u.x - std::round(u.x)) > 0.05f || std::abs(u.y - std::round(u.y)) > 0.05f) ++unsnappedFractional;
    }
  }
  EXPECT_EQ(snappedChecks, 96);
  EXPECT_GE(unsnappedFractional, 40);  // without snapping the grid slides by fractions of texels
}

TEST(Cascaded, LispsmWarpInsideEachSplitStillCoversTheSplit) {
  Scene scene = loadScene("columns", defaultAssetsDir());
  const Camera& cam = scene.cameras.front();
  LightSpace ls = cascadesFor(scene, cam, {"cascades.warp=lispsm"});
  const Bounds b = scene.boundsAt(0);
  const glm::mat4 view = cameraView(cam), proj = cameraProjection(cam, 16.0f / 9.0f);
  for (size_t i = 0; i < ls.views.size(); ++i) {
    EXPECT_TRUE(ls.views[i].perspective);
    float far = std::min(ls.views[i].splitFar, cam.farPlane);
    for (const auto& p : clipFrustumToBox(view, sliceProjection(proj, ls.views[i].splitNear, far), b)) {
      glm::vec4 c = ls.views[i].viewProj * glm::vec4(p, 1.0f);
      ASSERT_GT(c.w, 0.0f);
      EXPECT_LE(std::abs(c.x / c.w), 1.001f) << "split " << i;
      EXPECT_LE(std::abs(c.y / c.w), 1.001f) << "split " << i;
    }
  }
}

}  // namespace
}  // namespace sl
