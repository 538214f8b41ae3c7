#include "scene/volume_density.h"

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

// PCG-style integer hash; GLSL uint arithmetic wraps exactly like uint32_t.
uint32_t hash3(int32_t x, int32_t y, int32_t z, uint32_t seed) {
  uint32_t h = static_cast<uint32_t>(x) * 73856093u ^ static_cast<uint32_t>(y) * 19349663u ^
               static_cast<uint32_t>(z) * 83492791u ^ seed * 2654435761u;
  h = h * 747796405u + 2891336453u;
  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
  return (h >> 22u) ^ h;
}

float lattice(int32_t x, int32_t y, int32_t z, uint32_t seed) {
  return static_cast<float>(hash3(x, y, z, seed) >> 8u) * (1.0f / 16777216.0f);  // 24 bits: exact in float
}

float smooth(float t) { return t * t * (3.0f - 2.0f * t); }

float valueNoise(glm::vec3 p, uint32_t seed) {
  const glm::vec3 f = glm::floor(p);
  const glm::vec3 t = p - f;
  const int32_t x = static_cast<int32_t>(f.x), y = static_cast<int32_t>(f.y), z = static_cast<int32_t>(f.z);
  const float u = smooth(t.x), v = smooth(t.y), w = smooth(t.z);
  auto lerp = [](float a, float b, float s) { return a + (b - a) * s; };
  const float x00 = lerp(lattice(x, y, z, seed), lattice(x + 1, y, z, seed), u);
  const float x10 = lerp(lattice(x, y + 1, z, seed), lattice(x + 1, y + 1, z, seed), u);
  const float x01 = lerp(lattice(x, y, z + 1, seed), lattice(x + 1, y, z + 1, seed), u);
  const float x11 = lerp(lattice(x, y + 1, z + 1, seed), lattice(x + 1, y + 1, z + 1, seed), u);
  return lerp(lerp(x00, x10, v), lerp(x01, x11, v), w);
}

bool inside(const Volume& v, const glm::vec3& p) {
  const glm::vec3 d = p - v.center;
  if (v.shape == Volume::Shape::Sphere) return glm::dot(d, d) <= v.halfSize.x * v.halfSize.x;
  return std::abs(d.x) <= v.halfSize.x && std::abs(d.y) <= v.halfSize.y && std::abs(d.z) <= v.halfSize.z;
}

}  // namespace

float volumeFbm(glm::vec3 p, int octaves, uint32_t seed) {
  float sum = 0.0f, amplitude = 0.5f, total = 0.0f;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * valueNoise(p, seed + static_cast<uint32_t>(o));
    total += amplitude;
    p *= 2.0f;
    amplitude *= 0.5f;
  }
  return total > 0.0f ? sum / total : 0.0f;
}

float volumeExtinction(const Volume& v, const glm::vec3& p) {
  if (!inside(v, p)) return 0.0f;
  if (v.noise <= 0.0f) return v.extinction;
  // Contrast-stretched fBm (values cluster around 0.5): puffs with clear gaps between them.
  const float n =
      std::clamp(2.5f * (volumeFbm((p - v.center) * v.noiseScale, v.octaves, v.seed) - 0.5f) + 0.5f, 0.0f, 1.0f);
  return v.extinction * ((1.0f - v.noise) + v.noise * n);
}

bool volumeRange(const Volume& v, const glm::vec3& origin, const glm::vec3& dir, float& t0, float& t1) {
  const glm::vec3 o = origin - v.center;
  if (v.shape == Volume::Shape::Sphere) {
    const float b = glm::dot(o, dir), c = glm::dot(o, o) - v.halfSize.x * v.halfSize.x;
    const float a = glm::dot(dir, dir);
    const float disc = b * b - a * c;
    if (!(disc > 0.0f) || !(a > 0.0f)) return false;
    const float s = std::sqrt(disc);
    t0 = (-b - s) / a;
    t1 = (-b + s) / a;
    return true;
  }
  t0 = -1e30f;
  t1 = 1e30f;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(dir[k]) < 1e-12f) {
      if (std::abs(o[k]) > v.halfSize[k]) return false;
      continue;
    }
    float a = (-v.halfSize[k] - o[k]) / dir[k], b = (v.halfSize[k] - o[k]) / dir[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 < t1;
}

float volumeTransmittance(const Scene& scene, const glm::vec3& origin, const glm::vec3& dir, float tfar, int steps) {
  double opticalDepth = 0.0;
  for (const Volume& v : scene.volumes) {
    float t0, t1;
    if (!volumeRange(v, origin, dir, t0, t1)) continue;
    t0 = std::max(t0, 0.0f);
    t1 = std::min(t1, tfar);
    if (!(t1 > t0)) continue;
    const float dt = (t1 - t0) / static_cast<float>(steps);
    for (int s = 0; s < steps; ++s)
      opticalDepth += static_cast<double>(volumeExtinction(v, origin + dir * (t0 + (s + 0.5f) * dt))) * dt;
  }
  return static_cast<float>(std::exp(-opticalDepth));
}

}  // namespace sl
