// The density of a procedural medium (Scene::volumes): value-noise fBm on an integer-hashed
// lattice, written so that shaders/common/volume_density.glsl computes the same numbers (the
// hash is exact 32-bit integer arithmetic in both; tests/volume_density_gl_test compares them).
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

namespace sl {

// Noise in [0,1] at p (lattice units), `octaves` >= 1 octaves of value noise, seeded.
float volumeFbm(glm::vec3 p, int octaves, uint32_t seed);
// Extinction coefficient sigma_t (per world unit) at world point p: 0 outside the shape.
float volumeExtinction(const Volume& v, const glm::vec3& p);
// Ray parameters [t0, t1] where origin + t*dir is inside the shape; false when it misses.
bool volumeRange(const Volume& v, const glm::vec3& origin, const glm::vec3& dir, float& t0, float& t1);
// Transmittance exp(-integral of sigma_t) along origin + t*dir, t in [0, tfar], over every
// volume of the scene, by the midpoint rule with `steps` steps per volume crossed.
float volumeTransmittance(const Scene& scene, const glm::vec3& origin, const glm::vec3& dir, float tfar, int steps);

}  // namespace sl
