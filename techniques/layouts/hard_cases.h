// The numerically hard cases (camera and light set-ups on the basic scene), shared by
// the GL tests of every family that must stay finite on them.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <functional>
#include <string>
#include <vector>

namespace sl {

struct HardCase {
  std::string name;
  std::function<void(Scene&, Camera&)> setup;
};

inline void look(Camera& c, glm::vec3 from, glm::vec3 dir) {
  c.position = from;
  c.target = from + glm::normalize(dir) * 5.0f;
}

inline std::vector<HardCase> hardCases() {
  return {
      {"light behind the viewer, looking down the light",
       [](Scene& s, Camera& c) { look(c, glm::vec3(2.0f, 5.0f, 3.0f), s.light.direction); }},
      {"light along the view direction, toward the viewer",
       [](Scene& s, Camera& c) {
         look(c, glm::vec3(0.5f, 0.6f, 5.0f), glm::vec3(0.0f, 0.15f, -1.0f));
         s.light.direction = -glm::normalize(c.target - c.position);
       }},
      {"light parallel to the ground",
       [](Scene& s, Camera&) { s.light.direction = glm::normalize(glm::vec3(-1.0f, 0.0f, 0.3f)); }},
      {"near 0.01, far 10000",
       [](Scene&, Camera& c) {
         c.nearPlane = 0.01f;
         c.farPlane = 10000.0f;
       }},
      {"camera inside a caster",
       [](Scene&, Camera& c) { look(c, glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(1, -0.2f, 1)); }},
      {"camera and light straight down (view along its up vector)",
       [](Scene& s, Camera& c) {
         look(c, glm::vec3(0.3f, 6.0f, 0.2f), glm::vec3(0.0f, -1.0f, 0.0f));
         c.up = glm::vec3(0.0f, 1.0f, 0.0f);
         s.light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
       }},
      {"a scene that is one flat plane",
       [](Scene& s, Camera&) {
         s.instances.resize(1);  // basic's first object is its ground
       }},
      {"casters behind the camera",
       [](Scene& s, Camera& c) {
         look(c, glm::vec3(-1.5f, 1.5f, -1.5f), glm::vec3(-1.0f, -0.4f, -1.0f));
         s.light.direction = glm::normalize(glm::vec3(-1.0f, -0.5f, -1.0f));
       }},
  };
}

}  // namespace sl
