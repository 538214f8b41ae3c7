// Tests for scene motion: oscillating and rotating instances, the builtin moving scene, and the
// motion envelope that light views fitted over all of a scene's motion use.
#include "tests/assets_dir.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <string>

namespace sl {
namespace {

using test::kAssets;

TEST(SceneMotion, OscillateAndRotate) {
  Motion none;
  EXPECT_EQ(none.at(1.3), glm::mat4(1.0f));
  Motion osc;
  osc.type = Motion::Type::Oscillate;
  osc.vector = {2, 0, 0};
  osc.period = 4;
  EXPECT_NEAR((osc.at(1.0) * glm::vec4(0, 0, 0, 1)).x, 2.0f, 1e-5f);  // quarter period: +amplitude
  EXPECT_NEAR((osc.at(2.0) * glm::vec4(0, 0, 0, 1)).x, 0.0f, 1e-5f);
  EXPECT_NEAR((osc.at(3.0) * glm::vec4(0, 0, 0, 1)).x, -2.0f, 1e-5f);
  EXPECT_NEAR((osc.at(401.0) * glm::vec4(0, 0, 0, 1)).x, 2.0f, 1e-4f);  // periodic
  Motion rot;
  rot.type = Motion::Type::Rotate;
  rot.vector = {0, 1, 0};
  rot.period = 8;
  const glm::vec4 p = rot.at(2.0) * glm::vec4(1, 0, 0, 1);  // quarter turn about +Y: +X -> -Z
  EXPECT_NEAR(p.x, 0.0f, 1e-5f);
  EXPECT_NEAR(p.z, -1.0f, 1e-5f);
  Instance inst;
  inst.transform = glm::translate(glm::mat4(1.0f), {0, 5, 0});
  inst.motion = osc;
  EXPECT_NEAR((inst.transformAt(1.0) * glm::vec4(0, 0, 0, 1)).x, 2.0f, 1e-5f);
}

TEST(SceneBuiltin, MovingSceneMoves) {
  const Scene s = loadScene("moving", kAssets);
  EXPECT_TRUE(s.hasMotion());
  const Instance* sphere = nullptr;
  for (const Instance& i : s.instances) {
    if (i.name == "sphere") sphere = &i;
  }
  ASSERT_NE(sphere, nullptr);
  // The sphere orbits the pivot (0,1.5,0) at radius 2.5: its centre stays 2.5 from it.
  const Mesh& m = s.meshes[sphere->mesh];
  Bounds meshBounds;
  for (const auto& p : m.positions) meshBounds.add(p);
  const glm::vec3 local = meshBounds.center();
  for (double t : {0.0, 1.0, 1.5, 4.0}) {
    const glm::vec3 c = glm::vec3(sphere->transformAt(t) * glm::vec4(local, 1.0f));
    EXPECT_NEAR(glm::length(c - glm::vec3(0, 1.5f, 0)), 2.5f, 1e-3f) << t;
    EXPECT_NEAR(c.y, 1.5f, 1e-3f);
  }
  const glm::vec3 c0 = glm::vec3(sphere->transformAt(0.0) * glm::vec4(local, 1.0f));
  const glm::vec3 c1 = glm::vec3(sphere->transformAt(1.5) * glm::vec4(local, 1.0f));
  EXPECT_GT(glm::length(c1 - c0), 1.0f);
}

// The motion envelope holds the scene at every time (sampled densely over both periods), is no
// bigger than the sweep allows (the sphere orbits at radius 2.5 + 0.5, the box oscillates 2 + 0.5
// to each side), and is the plain bounds for a scene without motion.
TEST(SceneBuiltin, MotionEnvelopeHoldsTheSceneAtEveryTime) {
  const Scene s = loadScene("moving", kAssets);
  const Bounds envelope = s.motionEnvelope();
  for (int k = 0; k <= 240; ++k) {
    const Bounds b = s.boundsAt(k * 0.05);
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(envelope.min[a], b.min[a] + 1e-4f) << "t " << k * 0.05;
      EXPECT_GE(envelope.max[a], b.max[a] - 1e-4f) << "t " << k * 0.05;
    }
  }
  EXPECT_LE(envelope.max.x, 10.0f + 1e-3f);  // the 20 x 20 ground decides x and z
  EXPECT_LE(envelope.max.y, 1.5f + 3.0f + 1e-3f);
  const Scene still = loadScene("columns", kAssets);
  EXPECT_EQ(still.motionEnvelope().min, still.boundsAt(0.0).min);
  EXPECT_EQ(still.motionEnvelope().max, still.boundsAt(0.0).max);
}

}  // namespace
}  // namespace sl
