// First-person "fly" camera for the explorer: yaw/pitch around the world Y axis plus free
// translation. It knows nothing about windows or ImGui; the app turns input into FlyInput.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

namespace sl {

// What the user asks of the camera during one frame.
struct FlyInput {
  glm::vec3 move{0.0f};        // x = right, y = up, z = forward; each component in -1..1
  bool fast = false;           // shift held: move several times faster
  glm::vec2 lookPixels{0.0f};  // mouse movement while the look button is held
  float scrollSteps = 0.0f;    // mouse-wheel notches: change the movement speed
  bool empty() const;
};

class FlyCamera {
 public:
  // Places the camera at a scene camera. The movement speed is a fraction of the scene's
  // diagonal per second (speedFactor), so a small test scene and a large glTF feel alike.
  void jumpTo(const Camera& camera, float sceneDiagonal);
  // Follows a pose (camera path playback) without touching the speed.
  void setPose(const Camera& camera);
  // Applies one frame of input; returns true when position or orientation changed.
  bool update(const FlyInput& input, float dtSeconds);

  Camera camera() const;                                      // fov/near/far/name of the scene camera it started from
  float speed() const { return speedFactor_ * sceneScale_; }  // world units per second
  // Scene diagonals per second (the wheel multiplies it by 1.25 per notch).
  float speedFactor() const { return speedFactor_; }
  void setSpeedFactor(float factor);
  static constexpr float kDefaultSpeedFactor = 0.06f;  // ~17 s to cross the scene, 4 s with Shift
  static constexpr float kMinSpeedFactor = 0.002f, kMaxSpeedFactor = 2.0f;
  glm::vec3 forward() const;

 private:
  Camera base_;
  glm::vec3 position_{0.0f};
  float yaw_ = 0.0f;          // radians, 0 = looking down +X
  float pitch_ = 0.0f;        // radians, clamped short of straight up/down so "up" stays defined
  float sceneScale_ = 10.0f;  // the scene's diagonal (world units)
  float speedFactor_ = kDefaultSpeedFactor;
};

}  // namespace sl
