#include "reconstruction/silhouette_edges.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace sl {

namespace {

// Positions are welded on a grid of 1e-6 of the mesh's size: procedural seams (a sphere's
// sin(2 pi) != 0) and exported ones differ in the last bits, and an unwelded seam reads as an
// open rim, that is, as a silhouette.
struct PosHash {
  size_t operator()(const glm::i64vec3& p) const {
    return static_cast<size_t>(p.x * 73856093LL) ^ static_cast<size_t>(p.y * 19349663LL) ^
           static_cast<size_t>(p.z * 83492791LL);
  }
};

}  // namespace

MeshEdges buildMeshEdges(const Mesh& mesh) {
  MeshEdges m;
  Bounds b;
  for (const glm::vec3& p : mesh.positions) b.add(p);
  const float extent = b.empty() ? 1.0f : glm::max(glm::max(b.extent().x, b.extent().y), b.extent().z);
  const double cell = std::max(1e-6 * static_cast<double>(extent), 1e-12);
  std::unordered_map<glm::i64vec3, uint32_t, PosHash> weld;
  std::vector<uint32_t> remap(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::dvec3 q = glm::round(glm::dvec3(mesh.positions[i]) / cell);
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) {
      remap[i] = static_cast<uint32_t>(m.positions.size());  // never welded; its faces drop below
      m.positions.push_back(mesh.positions[i]);
      continue;
    }
    auto [it, inserted] = weld.try_emplace(glm::i64vec3(q), static_cast<uint32_t>(m.positions.size()));
    if (inserted) m.positions.push_back(mesh.positions[i]);
    remap[i] = it->second;
  }
  std::unordered_map<uint64_t, size_t> edgeOf;
  auto addEdge = [&](uint32_t a, uint32_t b, int32_t face) {
    const uint64_t key = (static_cast<uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
    auto [it, inserted] = edgeOf.try_emplace(key, m.edges.size());
    if (inserted) {
      m.edges.push_back({a, b, face, -1, true});
      return;
    }
    MeshEdges::Edge& e = m.edges[it->second];
    if (e.f1 < 0)
      e.f1 = face;
    else
      e.manifold = false;
  };
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    if (i0 >= remap.size() || i1 >= remap.size() || i2 >= remap.size()) continue;  // loader validated; be safe
    const glm::uvec3 f(remap[i0], remap[i1], remap[i2]);
    if (f.x == f.y || f.y == f.z || f.x == f.z) continue;  // degenerate: no facing, no edge
    const int32_t face = static_cast<int32_t>(m.faces.size());
    m.faces.push_back(f);
    addEdge(f.x, f.y, face);
    addEdge(f.y, f.z, face);
    addEdge(f.z, f.x, face);
  }
  return m;
}

void appendSilhouettes(const MeshEdges& m, const glm::mat4& model, const Light& light, std::vector<glm::vec3>& out) {
  std::vector<glm::vec3> world(m.positions.size());
  for (size_t i = 0; i < world.size(); ++i) world[i] = glm::vec3(model * glm::vec4(m.positions[i], 1.0f));
  // Facing sign per face in world space (a mirrored transform flips every face alike, so the
  // sign changes between neighbours stay the same).
  std::vector<int8_t> front(m.faces.size());
  for (size_t f = 0; f < m.faces.size(); ++f) {
    const glm::vec3 &p0 = world[m.faces[f].x], &p1 = world[m.faces[f].y], &p2 = world[m.faces[f].z];
    const glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
    const glm::vec3 toLight = light.positional() ? light.position - p0 : -light.direction;
    front[f] = glm::dot(n, toLight) > 0.0f ? 1 : 0;
  }
  for (const MeshEdges::Edge& e : m.edges) {
    const bool silhouette =
        !e.manifold || e.f1 < 0 || front[static_cast<size_t>(e.f0)] != front[static_cast<size_t>(e.f1)];
    if (!silhouette) continue;
    out.push_back(world[e.a]);
    out.push_back(world[e.b]);
  }
}

const std::vector<glm::vec3>& SilhouetteEdges::update(const Scene& scene, const Light& l, double time) {
  changed_ = false;
  // A scene edited in place (tests drop instances, move the light) at the same address is
  // caught by its counts and its light.
  const size_t shape = scene.triangleCount() * 31 + scene.meshes.size() * 7 + scene.instances.size();
  if (&scene != scene_ || shape != triangles_ || scene.sourcePath != source_) {
    scene_ = &scene;
    triangles_ = shape;
    source_ = scene.sourcePath;
    meshes_.clear();
    for (const Mesh& mesh : scene.meshes) meshes_.push_back(buildMeshEdges(mesh));
    time_ = -1e30;
  }
  const bool sameLight = l.type == light_.type && l.direction == light_.direction && l.position == light_.position;
  const bool sameTime = time == time_ || !scene.hasMotion();
  if (sameLight && sameTime && time_ > -1e29) return segments_;
  light_ = l;
  time_ = time;
  segments_.clear();
  for (const Instance& inst : scene.instances)
    if (inst.mesh >= 0 && static_cast<size_t>(inst.mesh) < meshes_.size())
      appendSilhouettes(meshes_[static_cast<size_t>(inst.mesh)], inst.transformAt(time), l, segments_);
  changed_ = true;
  return segments_;
}

}  // namespace sl
