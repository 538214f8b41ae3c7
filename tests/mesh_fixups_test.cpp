// Loader fix-ups that the renderer relies on: finite unit normals from glTF files that carry
// zero or NaN ones, and front faces that stay front faces under mirroring transforms (glTF
// nodes and scene JSON objects and models).
#include "tests/assets_dir.h"
#include "scene/mesh_ops.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#ifndef SHADOWLAB_SOURCE_DIR
#define SHADOWLAB_SOURCE_DIR "."
#endif

namespace sl {
namespace {

namespace fs = std::filesystem;

using test::kAssets;

std::string writeFile(const std::string& name, const std::string& text) {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("shadowlab_mesh_fixups_test_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  const fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string base64(const std::vector<uint8_t>& in) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < in.size(); i += 3) {
    const uint32_t b = uint32_t(in[i]) << 16 | (i + 1 < in.size() ? uint32_t(in[i + 1]) << 8 : 0u) |
                       (i + 2 < in.size() ? uint32_t(in[i + 2]) : 0u);
    out += table[b >> 18 & 63];
    out += table[b >> 12 & 63];
    out += i + 1 < in.size() ? table[b >> 6 & 63] : '=';
    out += i + 2 < in.size() ? table[b & 63] : '=';
  }
  return out;
}

void appendFloats(std::vector<uint8_t>& out, const std::vector<float>& v) {
  const size_t at = out.size();
  out.resize(at + v.size() * sizeof(float));
  std::memcpy(out.data() + at, v.data(), v.size() * sizeof(float));
}

// One counter-clockwise triangle in the XY plane (front face +z) with the given per-vertex
// normals, in a buffer embedded as base64; `nodes` is the JSON array of nodes using mesh 0.
std::string writeTriangleGltf(const std::string& stem, const std::vector<float>& normals, const std::string& nodes) {
  std::vector<uint8_t> bin;
  appendFloats(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});
  appendFloats(bin, normals);
  std::string roots;
  for (size_t i = 0, n = size_t(std::count(nodes.begin(), nodes.end(), '{')); i < n; ++i)
    roots += (i ? "," : "") + std::to_string(i);
  const std::string json = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[)" + roots + R"(]}],
    "nodes":)" + nodes + R"(,
    "buffers":[{"uri":"data:application/octet-stream;base64,)" +
                           base64(bin) + R"(","byteLength":72}],
    "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":36}],
    "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                 {"bufferView":1,"componentType":5126,"count":3,"type":"VEC3"}],
    "meshes":[{"name":"tri","primitives":[{"attributes":{"POSITION":0,"NORMAL":1}}]}]})";
  return writeFile(stem + ".gltf", json);
}

// For every triangle of every instance: the geometric normal of its world-space corners in
// index order (what culling and gl_FrontFacing see as the front) agrees with each corner's
// normal moved to world space the way gbuffer.vert does it.
void expectFrontFacesMatchNormals(const Scene& s) {
  for (const Instance& inst : s.instances) {
    const Mesh& m = s.meshes[size_t(inst.mesh)];
    const glm::mat4 model = inst.transformAt(0.0);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(model)));
    int wrong = 0;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      glm::vec3 p[3];
      for (int k = 0; k < 3; ++k) p[k] = glm::vec3(model * glm::vec4(m.positions[m.indices[t + k]], 1.0f));
      const glm::vec3 g = glm::cross(p[1] - p[0], p[2] - p[0]);
      if (glm::length(g) < 1e-12f) continue;
      for (int k = 0; k < 3; ++k) wrong += glm::dot(g, normalMatrix * m.normals[m.indices[t + k]]) > 0.0f ? 0 : 1;
    }
    EXPECT_EQ(wrong, 0) << inst.name << ": corners whose normal disagrees with the winding";
  }
}

TEST(MeshFixups, ZeroAndNanGltfNormalsBecomeFlatUnitNormals) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::string path = writeTriangleGltf("bad_normals", {0, 0, 0, nan, 0, 1, 0, 0, 2}, R"([{"mesh":0}])");
  testing::internal::CaptureStderr();
  const Scene s = loadScene(path, kAssets);
  const std::string err = testing::internal::GetCapturedStderr();
  ASSERT_EQ(s.instances.size(), 1u);
  const Mesh& m = s.meshes[size_t(s.instances[0].mesh)];
  ASSERT_EQ(m.normals.size(), m.positions.size());
  for (const glm::vec3& n : m.normals) {
    EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    EXPECT_NEAR(n.z, 1.0f, 1e-6f);  // the triangle's face normal; the good (0,0,2) normalized
  }
  // Said once for the file, with its name and how many normals were replaced.
  EXPECT_NE(err.find(path), std::string::npos) << err;
  EXPECT_NE(err.find(": 2 vertex normals"), std::string::npos) << err;
  EXPECT_EQ(err.find(path), err.rfind(path)) << err;
}

TEST(MeshFixups, BadNormalSharedByTrianglesFacingApartIsSplit) {
  // Two triangles sharing vertex 0 with opposite windings (a two-sided card): the average of
  // their face normals is zero, so the bad shared vertex gets one copy per triangle.
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  m.normals = {{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  m.uvs.assign(4, glm::vec2(0.0f));
  m.indices = {0, 1, 2, 0, 1, 3};
  EXPECT_EQ(repairNormals(m), 1u);
  ASSERT_EQ(m.positions.size(), 5u);
  EXPECT_EQ(m.normals[m.indices[0]], glm::vec3(0, 0, 1));
  EXPECT_EQ(m.normals[m.indices[3]], glm::vec3(0, 0, -1));
  EXPECT_EQ(m.positions[m.indices[3]], glm::vec3(0, 0, 0));
  // Good normals are only made unit length; nothing is split.
  Mesh good = m;
  good.normals[1] = {0, 0, 3};
  EXPECT_EQ(repairNormals(good), 0u);
  EXPECT_EQ(good.positions.size(), 5u);
  EXPECT_EQ(good.normals[1], glm::vec3(0, 0, 1));
}

TEST(MeshFixups, MirroredGltfNodeKeepsFrontFacesOutward) {
  // Node 0 mirrors (scale -1 on x), node 1 shares the mesh unmirrored, node 2 mirrors twice.
  const std::string path = writeTriangleGltf("mirrored", {0, 0, 1, 0, 0, 1, 0, 0, 1},
                                             R"([{"mesh":0,"scale":[-1,1,1]},{"mesh":0,"translation":[3,0,0]},
        {"mesh":0,"scale":[-1,-1,1],"translation":[6,0,0]}])");
  const Scene s = loadScene(path, kAssets);
  ASSERT_EQ(s.instances.size(), 3u);
  expectFrontFacesMatchNormals(s);
  // The mirrored node draws its own copy; the others share the original.
  EXPECT_NE(s.instances[0].mesh, s.instances[1].mesh);
  EXPECT_EQ(s.instances[1].mesh, s.instances[2].mesh);
  // Through a scene JSON model whose transform mirrors too: node 0 is mirrored twice (the
  // original winding), nodes 1 and 2 once.
  const std::string scene = writeFile("mirrored_model.json", R"({"models":[
      {"file":")" + path + R"(","transform":{"scale":[1,1,-1]}}]})");
  const Scene viaJson = loadScene(scene, kAssets);
  expectFrontFacesMatchNormals(viaJson);
  EXPECT_EQ(viaJson.instances[1].mesh, viaJson.instances[2].mesh);
  EXPECT_NE(viaJson.instances[0].mesh, viaJson.instances[1].mesh);
}

TEST(MeshFixups, MirroredSceneJsonObjectsKeepFrontFacesOutward) {
  const std::string path = writeFile("mirrored_objects.json", R"({"objects":[
      {"name":"plain","shape":"box","size":[1,2,3]},
      {"name":"scaled","shape":"box","size":[1,2,3],"transform":{"scale":[-1,1,1]}},
      {"name":"matrix","shape":"sphere","transform":{"matrix":[1,0,0,0, 0,-2,0,0, 0,0,1,0, 0,0,0,1]}},
      {"name":"twice","shape":"cylinder","transform":{"scale":[-1,-1,1]}},
      {"name":"pivot","shape":"box","transform":{"translate":[2,0,0],"scale":[1,1,-1]},
       "motion":{"type":"rotate","axis":[0,1,0],"pivot":[0,0,0],"period":4}}]})");
  const Scene s = loadScene(path, kAssets);
  ASSERT_EQ(s.instances.size(), 5u);
  expectFrontFacesMatchNormals(s);
}

}  // namespace
}  // namespace sl
