#include "scene/hair.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sl {

namespace {

// splitmix64: deterministic on every platform, unlike the std distributions.
struct Random {
  uint64_t state;
  float next() {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return static_cast<float>(z >> 40) * (1.0f / 16777216.0f);
  }
};

struct Root {
  glm::vec3 position, normal;
};

std::vector<Root> sampleRoots(const Scene& scene, const Instance& inst, const HairSpec& spec,
                              const std::string& where) {
  const Mesh& mesh = scene.meshes.at(static_cast<size_t>(inst.mesh));
  const glm::mat4 m = inst.transformAt(0.0);
  std::vector<glm::vec3> world(mesh.positions.size());
  for (size_t i = 0; i < world.size(); ++i) world[i] = glm::vec3(m * glm::vec4(mesh.positions[i], 1.0f));
  std::vector<double> cumulative;
  double total = 0.0;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3 &a = world[mesh.indices[t]], &b = world[mesh.indices[t + 1]], &c = world[mesh.indices[t + 2]];
    total += 0.5 * glm::length(glm::cross(b - a, c - a));
    cumulative.push_back(total);
  }
  if (!(total > 0.0) || !std::isfinite(total))
    throw SceneError(scene.sourcePath + ": " + where + ".on: object '" + spec.on + "' has no surface area to grow on");
  Random rng{spec.seed * 0x2545F4914F6CDD1Dull + 1};
  std::vector<Root> roots;
  for (int s = 0; s < spec.count; ++s) {
    const double pick = rng.next() * total;
    const size_t tri =
        std::min(static_cast<size_t>(std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()),
                 cumulative.size() - 1);
    float u = rng.next(), v = rng.next();
    if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
    const glm::vec3 &a = world[mesh.indices[3 * tri]], &b = world[mesh.indices[3 * tri + 1]],
                    &c = world[mesh.indices[3 * tri + 2]];
    glm::vec3 n = glm::cross(b - a, c - a);
    n = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0, 1, 0);
    roots.push_back({a + u * (b - a) + v * (c - a), n});
  }
  return roots;
}

void basis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  t = glm::normalize(glm::cross(helper, n));
  b = glm::cross(n, t);
}

// Point s in [0,1] along a strand: out along the normal, bent down by the droop, around a helix.
glm::vec3 strandPoint(const Root& r, const HairSpec& spec, const glm::vec3& t, const glm::vec3& b, float phase,
                      float s) {
  const float angle = phase + glm::two_pi<float>() * spec.turns * s;
  const glm::vec3 axis = r.normal * (spec.length * s) + glm::vec3(0, -1, 0) * (spec.droop * spec.length * s * s);
  return r.position + axis + spec.curl * s * (std::cos(angle) * t + std::sin(angle) * b);
}

}  // namespace

void appendHair(Scene& scene, const HairSpec& spec, const std::string& where) {
  const Instance* target = nullptr;
  std::string names;
  for (const Instance& i : scene.instances) {
    if (i.name == spec.on) target = &i;
    names += (names.empty() ? "" : ", ") + i.name;
  }
  if (!target)
    throw SceneError(scene.sourcePath + ": " + where + ".on: no object named '" + spec.on + "' (objects: " + names +
                     ")");
  const Instance host = *target;  // scene.instances grows below
  if (spec.count == 0) return;    // no strands: nothing to draw (an empty mesh is no GL buffer)
  Mesh mesh;
  mesh.name = spec.name;
  Random rng{spec.seed * 0x9E3779B97F4A7C15ull + 7};
  for (const Root& r : sampleRoots(scene, host, spec, where)) {
    glm::vec3 t, b;
    basis(r.normal, t, b);
    const float phase = rng.next() * glm::two_pi<float>();
    // A fixed ribbon orientation per strand (random about the strand): flat ribbons seen edge-on
    // from the light would vanish, random ones average to the strand's expected coverage.
    const float spin = rng.next() * glm::pi<float>();
    const glm::vec3 side0 = std::cos(spin) * t + std::sin(spin) * b;
    const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
    for (int k = 0; k <= spec.segments; ++k) {
      const float s = static_cast<float>(k) / static_cast<float>(spec.segments);
      const glm::vec3 p = strandPoint(r, spec, t, b, phase, s);
      const glm::vec3 ahead = strandPoint(r, spec, t, b, phase, std::min(s + 1e-3f, 1.0f)) -
                              strandPoint(r, spec, t, b, phase, std::max(s - 1e-3f, 0.0f));
      const glm::vec3 tangent = glm::length(ahead) > 0.0f ? glm::normalize(ahead) : r.normal;
      glm::vec3 side = side0 - tangent * glm::dot(side0, tangent);
      side = glm::length(side) > 1e-6f ? glm::normalize(side) : t;
      const glm::vec3 normal = glm::normalize(glm::cross(tangent, side));
      for (float sign : {-0.5f, 0.5f}) {
        mesh.positions.push_back(p + side * (sign * spec.width));
        mesh.normals.push_back(normal);
        mesh.uvs.push_back(glm::vec2(sign + 0.5f, s));
      }
      if (k == 0) continue;
      const uint32_t i = base + 2 * static_cast<uint32_t>(k);
      mesh.indices.insert(mesh.indices.end(), {i - 2, i - 1, i, i - 1, i + 1, i});
    }
  }
  Material mat;
  mat.baseColor = glm::vec4(spec.color, spec.opacity);
  // Techniques without transmittance draw and cast strands as opaque; deep shadow maps attenuate.
  mat.alphaBlend = true;
  mat.doubleSided = true;
  scene.materials.push_back(mat);
  mesh.material = static_cast<int>(scene.materials.size() - 1);
  scene.meshes.push_back(std::move(mesh));
  Instance inst;
  inst.name = spec.name;
  inst.mesh = static_cast<int>(scene.meshes.size() - 1);
  scene.instances.push_back(inst);
}

}  // namespace sl
