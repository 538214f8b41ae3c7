#include "scene/shapes.h"

#include <algorithm>
#include <cmath>

namespace sl {
namespace {

constexpr float kPi = 3.14159265358979323846f;

uint32_t addVertex(Mesh& m, const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
  m.positions.push_back(p);
  m.normals.push_back(n);
  m.uvs.push_back(uv);
  return static_cast<uint32_t>(m.positions.size() - 1);
}

// Grid of (cols+1)*(rows+1) vertices spanning origin + u*[0,1] + v*[0,1]; triangles wind so that
// their face normal is cross(u, v), which callers make equal to `normal`.
void addGrid(Mesh& m, const glm::vec3& origin, const glm::vec3& u, const glm::vec3& v, const glm::vec3& normal,
             int cols, int rows) {
  const uint32_t base = static_cast<uint32_t>(m.positions.size());
  for (int r = 0; r <= rows; ++r) {
    for (int c = 0; c <= cols; ++c) {
      const float s = float(c) / float(cols), t = float(r) / float(rows);
      addVertex(m, origin + u * s + v * t, normal, {s, t});
    }
  }
  const uint32_t stride = uint32_t(cols) + 1;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const uint32_t i0 = base + uint32_t(r) * stride + uint32_t(c);
      const uint32_t i1 = i0 + 1, i2 = i0 + stride, i3 = i2 + 1;
      m.indices.insert(m.indices.end(), {i0, i1, i3, i0, i3, i2});
    }
  }
}

}  // namespace

Mesh makePlane(float sizeX, float sizeZ, int subdivisions) {
  Mesh m;
  m.name = "plane";
  const int n = std::max(1, subdivisions);
  // u along +Z and v along +X gives cross(u, v) = +Y.
  addGrid(m, {-sizeX / 2, 0, -sizeZ / 2}, {0, 0, sizeZ}, {sizeX, 0, 0}, {0, 1, 0}, n, n);
  return m;
}

Mesh makeBox(const glm::vec3& size) {
  Mesh m;
  m.name = "box";
  const glm::vec3 h = size * 0.5f;
  const glm::vec3 dx{size.x, 0, 0}, dy{0, size.y, 0}, dz{0, 0, size.z};
  addGrid(m, {h.x, -h.y, -h.z}, dy, dz, {1, 0, 0}, 1, 1);    // +X
  addGrid(m, {-h.x, -h.y, -h.z}, dz, dy, {-1, 0, 0}, 1, 1);  // -X
  addGrid(m, {-h.x, h.y, -h.z}, dz, dx, {0, 1, 0}, 1, 1);    // +Y
  addGrid(m, {-h.x, -h.y, -h.z}, dx, dz, {0, -1, 0}, 1, 1);  // -Y
  addGrid(m, {-h.x, -h.y, h.z}, dx, dy, {0, 0, 1}, 1, 1);    // +Z
  addGrid(m, {-h.x, -h.y, -h.z}, dy, dx, {0, 0, -1}, 1, 1);  // -Z
  return m;
}

Mesh makeSphere(float radius, int segments) {
  Mesh m;
  m.name = "sphere";
  const int slices = std::max(3, segments);
  const int rings = std::max(2, segments / 2);
  for (int r = 0; r <= rings; ++r) {
    const float theta = kPi * float(r) / float(rings);  // 0 at the north pole
    for (int s = 0; s <= slices; ++s) {
      const float phi = 2.0f * kPi * float(s) / float(slices);
      const glm::vec3 n{std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)};
      addVertex(m, n * radius, n, {float(s) / float(slices), float(r) / float(rings)});
    }
  }
  const uint32_t stride = uint32_t(slices) + 1;
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < slices; ++s) {
      const uint32_t i0 = uint32_t(r) * stride + uint32_t(s);
      const uint32_t i1 = i0 + 1, i2 = i0 + stride, i3 = i2 + 1;
      // The pole rows have zero-area triangles on one side; skip those.
      if (r != 0) m.indices.insert(m.indices.end(), {i0, i2, i1});
      if (r != rings - 1) m.indices.insert(m.indices.end(), {i1, i2, i3});
    }
  }
  return m;
}

Mesh makeCylinder(float radius, float height, int segments, bool capped) {
  Mesh m;
  m.name = "cylinder";
  const int slices = std::max(3, segments);
  const float h = height * 0.5f;
  for (int s = 0; s <= slices; ++s) {
    const float phi = 2.0f * kPi * float(s) / float(slices);
    const glm::vec3 n{std::cos(phi), 0, -std::sin(phi)};
    const float u = float(s) / float(slices);
    addVertex(m, n * radius + glm::vec3(0, -h, 0), n, {u, 1});
    addVertex(m, n * radius + glm::vec3(0, h, 0), n, {u, 0});
  }
  for (int s = 0; s < slices; ++s) {
    const uint32_t b0 = uint32_t(s) * 2, t0 = b0 + 1, b1 = b0 + 2, t1 = b0 + 3;
    m.indices.insert(m.indices.end(), {b0, b1, t1, b0, t1, t0});
  }
  if (capped) {
    for (int side = 0; side < 2; ++side) {
      const float y = side == 0 ? h : -h;
      const glm::vec3 n{0, side == 0 ? 1.0f : -1.0f, 0};
      const uint32_t center = addVertex(m, {0, y, 0}, n, {0.5f, 0.5f});
      for (int s = 0; s <= slices; ++s) {
        const float phi = 2.0f * kPi * float(s) / float(slices);
        const float c = std::cos(phi), d = -std::sin(phi);
        addVertex(m, {c * radius, y, d * radius}, n, {0.5f + 0.5f * c, 0.5f + 0.5f * d});
      }
      for (int s = 0; s < slices; ++s) {
        const uint32_t a = center + 1 + uint32_t(s), b = a + 1;
        // The ring runs counter-clockwise seen from +Y, so the bottom cap reverses it.
        if (side == 0)
          m.indices.insert(m.indices.end(), {center, a, b});
        else
          m.indices.insert(m.indices.end(), {center, b, a});
      }
    }
  }
  return m;
}

}  // namespace sl
