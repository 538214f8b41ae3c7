// Generated hair: strands grown over the surface of a scene instance, as flat ribbons of
// triangles the rasterizer and the ray tracer both draw, with a semi-transparent material.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <string>

namespace sl {

struct HairSpec {
  std::string name = "hair";
  std::string on;        // instance the strands grow from
  int count = 1000;      // strands, >= 0
  float length = 0.3f;   // world units along the strand
  float curl = 0.0f;     // radius of the helix a strand winds around its axis, world units
  float turns = 2.0f;    // helix turns over the strand's length
  float width = 0.005f;  // ribbon width, world units
  float opacity = 0.3f;  // alpha of one strand, [0,1]
  float droop = 0.0f;    // how far the tip bends toward -y, fraction of the length
  int segments = 6;      // ribbon quads per strand
  glm::vec3 color{0.35f, 0.22f, 0.12f};
  uint32_t seed = 1;
};

// Appends the strands as one mesh, material and instance. The roots are sampled over the
// target's triangles by area with a deterministic generator (same seed, same hair everywhere).
// Throws SceneError("<file>: <where>...") when `on` names no instance or it has no area.
void appendHair(Scene& scene, const HairSpec& spec, const std::string& where);

}  // namespace sl
