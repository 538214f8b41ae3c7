#include "explorer/fly_camera.h"

#include <algorithm>
#include <cmath>

namespace sl {

namespace {
constexpr float kLookRadiansPerPixel = 0.003f;
constexpr float kFastFactor = 4.0f;
constexpr float kSpeedStepFactor = 1.25f;
constexpr float kMaxPitch = 1.55f;  // ~89 degrees: at 90 the view matrix's up vector degenerates
const glm::vec3 kWorldUp{0.0f, 1.0f, 0.0f};
}  // namespace

bool FlyInput::empty() const { return move == glm::vec3(0.0f) && lookPixels == glm::vec2(0.0f) && scrollSteps == 0.0f; }

void FlyCamera::setPose(const Camera& camera) {
  base_ = camera;
  position_ = camera.position;
  glm::vec3 dir = camera.target - camera.position;
  if (glm::length(dir) < 1e-6f) dir = glm::vec3(0.0f, 0.0f, -1.0f);
  dir = glm::normalize(dir);
  pitch_ = std::clamp(std::asin(std::clamp(dir.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
  yaw_ = std::atan2(dir.z, dir.x);
}

void FlyCamera::jumpTo(const Camera& camera, float sceneDiagonal) {
  setPose(camera);
  sceneScale_ = std::isfinite(sceneDiagonal) && sceneDiagonal > 0.0f ? sceneDiagonal : 10.0f;
}

void FlyCamera::setSpeedFactor(float factor) {
  if (std::isfinite(factor)) speedFactor_ = std::clamp(factor, kMinSpeedFactor, kMaxSpeedFactor);
}

glm::vec3 FlyCamera::forward() const {
  return {std::cos(pitch_) * std::cos(yaw_), std::sin(pitch_), std::cos(pitch_) * std::sin(yaw_)};
}

bool FlyCamera::update(const FlyInput& input, float dtSeconds) {
  if (input.scrollSteps != 0.0f) setSpeedFactor(speedFactor_ * std::pow(kSpeedStepFactor, input.scrollSteps));

  bool changed = false;
  if (input.lookPixels != glm::vec2(0.0f)) {
    yaw_ += input.lookPixels.x * kLookRadiansPerPixel;
    pitch_ = std::clamp(pitch_ - input.lookPixels.y * kLookRadiansPerPixel, -kMaxPitch, kMaxPitch);
    changed = true;
  }
  if (input.move != glm::vec3(0.0f)) {
    glm::vec3 fwd = forward();
    glm::vec3 right = glm::normalize(glm::cross(fwd, kWorldUp));
    float distance = speed() * (input.fast ? kFastFactor : 1.0f) * dtSeconds;
    position_ += distance * (right * input.move.x + kWorldUp * input.move.y + fwd * input.move.z);
    changed = true;
  }
  return changed;
}

Camera FlyCamera::camera() const {
  Camera c = base_;
  c.position = position_;
  c.target = position_ + forward();
  c.up = kWorldUp;
  return c;
}

}  // namespace sl
