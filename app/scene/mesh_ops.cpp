#include "scene/mesh_ops.h"

#include <cmath>
#include <utility>
#include <vector>

namespace sl {

// In double, so that large coordinates do not overflow the cross product; a degenerate
// triangle covers no pixel, so its normal only has to be finite.
static glm::vec3 faceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::dvec3 n = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
  const double len = glm::length(n);
  return len > 0.0 && std::isfinite(len) ? glm::vec3(n / len) : glm::vec3(0, 1, 0);
}

bool mirrors(const glm::mat4& m) { return glm::determinant(glm::mat3(m)) < 0.0f; }

void reverseWinding(Mesh& mesh) {
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
}

void makeFlatNormals(Mesh& m) {
  Mesh flat;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const uint32_t i[3] = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
    const glm::vec3 n = faceNormal(m.positions[i[0]], m.positions[i[1]], m.positions[i[2]]);
    for (uint32_t k : i) {
      flat.indices.push_back(uint32_t(flat.positions.size()));
      flat.positions.push_back(m.positions[k]);
      flat.normals.push_back(n);
      flat.uvs.push_back(m.uvs[k]);
    }
  }
  m.positions = std::move(flat.positions);
  m.normals = std::move(flat.normals);
  m.uvs = std::move(flat.uvs);
  m.indices = std::move(flat.indices);
}

// Exporters do write zero and NaN normals although glTF requires unit ones; normalize() in the
// shaders turns those into NaN shading and visibility. A bad vertex that several triangles
// share is split rather than given their average, which can cancel out (two-sided cards).
size_t repairNormals(Mesh& m) {
  std::vector<bool> bad(m.normals.size(), false);
  size_t count = 0;
  for (size_t i = 0; i < m.normals.size(); ++i) {
    const glm::dvec3 n(m.normals[i]);
    const double len = glm::length(n);
    bad[i] = !(len > 1e-12 && std::isfinite(len));
    count += bad[i] ? 1 : 0;
    if (!bad[i]) m.normals[i] = glm::vec3(n / len);
  }
  if (count == 0) return 0;
  std::vector<bool> assigned(m.normals.size(), false);
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    uint32_t* tri = &m.indices[t];
    const glm::vec3 n = faceNormal(m.positions[tri[0]], m.positions[tri[1]], m.positions[tri[2]]);
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = tri[k];
      if (!bad[v]) continue;
      if (!assigned[v]) {
        assigned[v] = true;
        m.normals[v] = n;
        continue;
      }
      tri[k] = uint32_t(m.positions.size());
      m.positions.push_back(m.positions[v]);
      m.normals.push_back(n);
      m.uvs.push_back(m.uvs[v]);
    }
  }
  // Vertices no triangle uses are never drawn, but every normal must be finite.
  for (size_t i = 0; i < bad.size(); ++i)
    if (bad[i] && !assigned[i]) m.normals[i] = glm::vec3(0, 1, 0);
  return count;
}

}  // namespace sl
