// FaceCache without a GPU: which faces keep their layer as the view, the technique and the
// moving instances change.
#include "point/face_cache.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace sl {
namespace {

// A unit box oscillating along x by `amplitude` (period 4 s: at t = 1 it is amplitude to +x).
Scene sceneWithMovingBox(float amplitude) {
  Scene s;
  Mesh m;
  m.positions = {{-0.5f, -0.5f, -0.5f}, {0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, {-0.5f, 0.5f, 0.5f}};
  m.indices = {0, 1, 2, 0, 2, 3};
  s.meshes.push_back(m);
  Instance moving;
  moving.mesh = 0;
  moving.motion.type = Motion::Type::Oscillate;
  moving.motion.vector = {amplitude, 0.0f, 0.0f};
  moving.motion.period = 4.0f;
  s.instances.push_back(moving);
  return s;
}

// A 90-degree view from the origin looking along `dir` out to 20 units.
glm::mat4 lookFromOrigin(glm::vec3 dir) {
  const glm::vec3 up = std::abs(dir.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 20.0f) * glm::lookAt(glm::vec3(0.0f), dir, up);
}

TEST(FaceCache, KeepsOnlyWhatIsUnchangedAndUntouchedByMotion) {
  // The box sits at x = 5 at t = 0 and oscillates to x = 8 at t = 1: always in the +x face.
  Scene scene = sceneWithMovingBox(3.0f);
  scene.instances[0].transform = glm::translate(glm::mat4(1.0f), glm::vec3(5, 0, 0));
  const std::vector<FaceContent> faces = {{.viewProj = lookFromOrigin({1, 0, 0}), .sceneGeneration = 1, .size = 64},
                                          {.viewProj = lookFromOrigin({-1, 0, 0}), .sceneGeneration = 1, .size = 64}};
  const std::vector<bool> needed = {true, true};
  FaceCache cache;
  EXPECT_EQ(cache.keep(faces, needed, scene, 0.0), (std::vector<bool>{false, false})) << "nothing held yet";
  cache.record(faces, {true, true}, true, 0.0);
  EXPECT_EQ(cache.keep(faces, needed, scene, 0.0), (std::vector<bool>{true, true})) << "the same frame again";
  // Time moves the box within +x: that face is drawn again, -x is kept.
  EXPECT_EQ(cache.keep(faces, needed, scene, 1.0), (std::vector<bool>{false, true}));
  // Another view, another technique stamp, size or scene: drawn again.
  for (auto change : {+[](FaceContent& c) { c.viewProj[3][0] += 0.01f; }, +[](FaceContent& c) { c.techniqueStamp++; },
                      +[](FaceContent& c) { c.size = 128; }, +[](FaceContent& c) { c.sceneGeneration = 2; }}) {
    std::vector<FaceContent> changed = faces;
    change(changed[1]);
    EXPECT_EQ(cache.keep(changed, needed, scene, 0.0), (std::vector<bool>{true, false}));
  }
  // A face not needed is never "kept" (it is not drawn either way); one the representation
  // cleared holds nothing.
  EXPECT_EQ(cache.keep(faces, {true, false}, scene, 0.0), (std::vector<bool>{true, false}));
  cache.record(faces, {true, false}, false, 0.0);
  EXPECT_EQ(cache.keep(faces, needed, scene, 0.0), (std::vector<bool>{true, false}));
  // A view that is no projective map (a paraboloid) is drawn again whenever something moved.
  std::vector<FaceContent> bent = faces;
  for (FaceContent& c : bent) c.projective = false;
  cache.record(bent, {true, true}, true, 0.0);
  EXPECT_EQ(cache.keep(bent, needed, scene, 1.0), (std::vector<bool>{false, false}));
  EXPECT_EQ(cache.keep(bent, needed, scene, 0.0), (std::vector<bool>{true, true}));
}

// Where the instance was when the layer was drawn counts too: a box that left a face must be
// erased from it.
TEST(FaceCache, AnInstanceThatLeftTheFaceRedrawsIt) {
  Scene scene = sceneWithMovingBox(10.0f);
  scene.instances[0].transform = glm::translate(glm::mat4(1.0f), glm::vec3(-5, 0, 0));
  // At t = 0 the box is at x = -5 (the -x face); at t = 1 at x = +5 (the +x face).
  const glm::mat4 minusX = lookFromOrigin({-1, 0, 0}), plusX = lookFromOrigin({1, 0, 0}),
                  up = lookFromOrigin({0, 1, 0});
  EXPECT_TRUE(movingInstanceInView(scene, minusX, 0.0, 0.0));
  EXPECT_FALSE(movingInstanceInView(scene, minusX, 1.0, 1.0));
  EXPECT_TRUE(movingInstanceInView(scene, minusX, 0.0, 1.0));
  EXPECT_TRUE(movingInstanceInView(scene, plusX, 0.0, 1.0));
  EXPECT_FALSE(movingInstanceInView(scene, up, 0.0, 1.0));
}

}  // namespace
}  // namespace sl
