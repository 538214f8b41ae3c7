// Tests for the scene module: JSON validation errors, glTF import, builtin scenes, motion, paths.
#include "tests/assets_dir.h"
#include "scene/scene.h"
#include "scene/scene_effects.h"
#include "scene/shapes.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
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

fs::path tempDir() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("shadowlab_scene_test_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

std::string writeFile(const std::string& name, const std::string& text) {
  const fs::path p = tempDir() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

// Loads `path` expecting a SceneError; returns its message (empty if nothing was thrown).
std::string loadError(const std::string& path) {
  try {
    loadScene(path, kAssets);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

const char* kGround = R"({"shape":"plane","size":[10,10]})";

// A scene with one valid ground plane plus `extra` top-level members.
std::string sceneWith(const std::string& extra) {
  return std::string(R"({"objects":[)") + kGround + "]" + (extra.empty() ? "" : "," + extra) + "}";
}

struct BadCase {
  const char* name;
  std::string json;
  std::vector<std::string> expectedWords;
};

TEST(SceneJson, BadFilesReportFileAndProblem) {
  const std::vector<BadCase> cases = {
      {"malformed", R"({"objects": [ )", {"malformed JSON", "byte"}},
      {"toplevel_typo", sceneWith(R"("camras":[])"), {"unknown key 'camras'"}},
      {"object_typo", R"({"objects":[{"shape":"box","colour":[1,0,0]}]})", {"objects[0].colour", "unknown key"}},
      {"light_typo", sceneWith(R"("light":{"dir":[0,-1,0]})"), {"light.dir", "unknown key"}},
      {"camera_typo",
       sceneWith(R"("cameras":[{"position":[0,1,5],"target":[0,0,0],"fov":60}])"),
       {"cameras[0].fov", "unknown key"}},
      {"path_key_typo",
       sceneWith(
           R"("paths":[{"keys":[{"time":0,"position":[0,1,5],"target":[0,0,0]},{"t":1,"position":[0,1,5],"target":[0,0,0]}]}])"),
       {"paths[0].keys[1].t", "unknown key"}},
      {"motion_typo",
       R"({"objects":[{"shape":"box","motion":{"type":"oscillate","vector":[1,0,0],"perod":2}}]})",
       {"unknown key 'perod'"}},
      {"key_for_other_shape", R"({"objects":[{"shape":"box","radius":1}]})", {"unknown key 'radius'"}},
      {"wrong_type",
       R"({"objects":[{"shape":"box","size":"big"}]})",
       {"objects[0].size", "expected 3 positive finite numbers"}},
      {"objects_not_array", R"({"objects":{"shape":"box"}})", {"objects", "expected an array"}},
      {"inf_literal", R"({"objects":[{"shape":"sphere","radius":1e999}]})", {"malformed JSON", "finite", "1e999"}},
      {"inf_in_vector", sceneWith(R"("light":{"direction":[0,-1e999,0]})"), {"finite", "-1e999"}},
      {"float_overflow",
       R"({"objects":[{"shape":"sphere","radius":1e300}]})",
       {"objects[0].radius", "positive finite number"}},
      {"float_overflow_vector", sceneWith(R"("light":{"direction":[0,-1e300,0]})"), {"light.direction", "finite"}},
      {"zero_size",
       std::string(R"({"objects":[)") + kGround + R"(,{"shape":"plane","size":[1,1]},{"shape":"box","size":[1,0,1]}]})",
       {"objects[2].size: expected 3 positive finite numbers, got [1,0,1]"}},
      {"negative_radius",
       R"({"objects":[{"shape":"cylinder","radius":-1,"height":2}]})",
       {"objects[0].radius", "positive"}},
      {"zero_light_dir", sceneWith(R"("light":{"direction":[0,0,0]})"), {"light.direction", "zero-length"}},
      {"near_zero",
       sceneWith(R"("cameras":[{"position":[0,1,5],"target":[0,0,0],"near":0}])"),
       {"cameras[0].near", "> 0"}},
      {"near_ge_far",
       sceneWith(R"("cameras":[{"position":[0,1,5],"target":[0,0,0],"near":10,"far":5}])"),
       {"cameras[0].far", "near must be < far"}},
      {"camera_pos_eq_target",
       sceneWith(R"("cameras":[{"position":[1,1,1],"target":[1,1,1]}])"),
       {"cameras[0]", "position equals target"}},
      {"fov_180",
       sceneWith(R"("cameras":[{"position":[0,1,5],"target":[0,0,0],"fov_deg":180}])"),
       {"fov_deg", "(0,180)"}},
      {"light_fov", sceneWith(R"("light":{"type":"spot","fov_deg":0})"), {"light.fov_deg", "(0,180)"}},
      {"path_one_key",
       sceneWith(R"("paths":[{"name":"p","keys":[{"time":0,"position":[0,1,5],"target":[0,0,0]}]}])"),
       {"paths[0].keys", "at least 2"}},
      {"path_times",
       sceneWith(
           R"("paths":[{"keys":[{"time":0,"position":[0,1,5],"target":[0,0,0]},{"time":0,"position":[0,1,4],"target":[0,0,0]}]}])"),
       {"paths[0].keys[1].time", "strictly increasing"}},
      {"unknown_shape", R"({"objects":[{"shape":"torus"}]})", {"objects[0].shape", "unknown shape 'torus'"}},
      {"unknown_light", sceneWith(R"("light":{"type":"area"})"), {"light.type", "unknown light type 'area'"}},
      {"missing_gltf",
       R"({"models":[{"file":"does_not_exist.gltf"}]})",
       {"models[0].file", "does_not_exist.gltf", "not found"}},
      {"empty_scene", R"({"name":"nothing"})", {"no triangles"}},
      {"empty_objects", R"({"objects":[]})", {"no triangles"}},
      {"bad_matrix", R"({"objects":[{"shape":"box","transform":{"matrix":[1,0,0]}}]})", {"transform.matrix", "16"}},
      {"zero_scale", R"({"objects":[{"shape":"box","transform":{"scale":[1,0,1]}}]})", {"transform.scale", "non-zero"}},
      {"duplicate_camera",
       sceneWith(
           R"("cameras":[{"position":[0,1,5],"target":[0,0,0]},{"name":"default","position":[0,2,5],"target":[0,0,0]}])"),
       {"cameras[1].name", "duplicate"}},
      {"not_object", "[1,2,3]", {"expected an object"}},
  };
  for (const BadCase& c : cases) {
    const std::string file = std::string("bad_") + c.name + ".json";
    const std::string path = writeFile(file, c.json);
    const std::string msg = loadError(path);
    ASSERT_FALSE(msg.empty()) << c.name << ": no SceneError";
    EXPECT_EQ(msg.rfind(path, 0), 0u) << c.name << ": message must start with the path: " << msg;
    for (const std::string& w : c.expectedWords) {
      EXPECT_NE(msg.find(w), std::string::npos) << c.name << ": '" << w << "' not in: " << msg;
    }
  }
}

TEST(SceneJson, MissingFileAndUnknownId) {
  const std::string missing = (tempDir() / "nope.json").string();
  EXPECT_NE(loadError(missing).find("cannot open"), std::string::npos);
  const std::string msg = loadError("no-such-scene");
  EXPECT_NE(msg.find("no-such-scene"), std::string::npos) << msg;
  EXPECT_NE(msg.find("basic"), std::string::npos) << "should list the available ids: " << msg;
  EXPECT_NE(loadError(writeFile("scene.txt", "{}")).find("unsupported"), std::string::npos);
}

TEST(SceneJson, DefaultsAndTransforms) {
  const std::string path = writeFile("defaults_scene.json", R"({"objects":[
      {"name":"b","shape":"box","size":[2,2,2],"transform":{"translate":[1,2,3],"rotate_deg":[0,90,0],"scale":2}},
      {"name":"m","shape":"box","transform":{"matrix":[1,0,0,0, 0,1,0,0, 0,0,1,0, 5,6,7,1]}}]})");
  const Scene s = loadScene(path, kAssets);
  EXPECT_EQ(s.name, "defaults_scene");  // file stem
  ASSERT_EQ(s.cameras.size(), 1u);      // automatic camera
  EXPECT_EQ(s.cameras[0].name, "default");
  EXPECT_LT(s.cameras[0].nearPlane, s.cameras[0].farPlane);
  EXPECT_LT(s.light.direction.y, -0.5f);  // automatic light from above
  ASSERT_EQ(s.instances.size(), 2u);
  // rotate_deg [0,90,0] turns +X into -Z; the translate applies last.
  const glm::vec4 p = s.instances[0].transform * glm::vec4(1, 0, 0, 1);
  EXPECT_NEAR(p.x, 1.0f, 1e-5f);
  EXPECT_NEAR(p.y, 2.0f, 1e-5f);
  EXPECT_NEAR(p.z, 3.0f - 2.0f, 1e-5f);
  const glm::vec4 q = s.instances[1].transform * glm::vec4(0, 0, 0, 1);
  EXPECT_EQ(glm::vec3(q), glm::vec3(5, 6, 7));
  // The automatic camera sees every corner of the bounds.
  const Bounds b = s.boundsAt(0.0);
  const glm::mat4 vp = cameraProjection(s.cameras[0], 1.0f) * cameraView(s.cameras[0]);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 c((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
    const glm::vec4 clip = vp * glm::vec4(c, 1.0f);
    ASSERT_GT(clip.w, 0.0f);
    for (int k = 0; k < 3; ++k) EXPECT_LE(std::fabs(clip[k] / clip.w), 1.0f);
  }
}

TEST(SceneShapes, NormalsPointOutwardAndWindingMatches) {
  const std::vector<Mesh> meshes = {makeBox({1, 2, 3}), makeSphere(1.0f, 16), makeCylinder(0.5f, 2.0f, 12, true),
                                    makePlane(4, 4, 3)};
  for (const Mesh& m : meshes) {
    ASSERT_EQ(m.normals.size(), m.positions.size()) << m.name;
    ASSERT_EQ(m.uvs.size(), m.positions.size()) << m.name;
    ASSERT_GT(m.indices.size(), 0u);
    for (size_t t = 0; t < m.indices.size(); t += 3) {
      const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                      c = m.positions[m.indices[t + 2]];
      const glm::vec3 face = glm::cross(b - a, c - a);
      ASSERT_GT(glm::length(face), 0.0f) << m.name << " degenerate triangle " << t / 3;
      const glm::vec3 centroid = (a + b + c) / 3.0f;
      const glm::vec3 outward = m.name == "plane" ? glm::vec3(0, 1, 0) : centroid;
      EXPECT_GT(glm::dot(face, outward), 0.0f) << m.name << " triangle " << t / 3;
      EXPECT_GT(glm::dot(face, m.normals[m.indices[t]]), 0.0f) << m.name;
    }
  }
}

TEST(SceneCameraPath, SampleIsPiecewiseLinearAndClamped) {
  CameraPath path;
  path.keys = {{0.0f, {0, 0, 0}, {0, 0, -1}}, {2.0f, {2, 0, 0}, {2, 0, -1}}, {4.0f, {2, 4, 0}, {2, 4, -1}}};
  Camera base;
  base.fovDeg = 45;
  EXPECT_FLOAT_EQ(path.duration(), 4.0f);
  EXPECT_EQ(path.sample(-1.0f, base).position, glm::vec3(0, 0, 0));
  EXPECT_EQ(path.sample(1.0f, base).position, glm::vec3(1, 0, 0));
  EXPECT_EQ(path.sample(2.0f, base).position, glm::vec3(2, 0, 0));
  EXPECT_EQ(path.sample(3.0f, base).position, glm::vec3(2, 2, 0));
  EXPECT_EQ(path.sample(3.0f, base).target, glm::vec3(2, 2, -1));
  EXPECT_EQ(path.sample(10.0f, base).position, glm::vec3(2, 4, 0));
  EXPECT_EQ(path.sample(1.0f, base).fovDeg, 45.0f);
}

void expectValidScene(const Scene& s) {
  EXPECT_GT(s.triangleCount(), 0u) << s.name;
  const Bounds b = s.boundsAt(0.0);
  ASSERT_FALSE(b.empty()) << s.name;
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(std::isfinite(b.min[k]) && std::isfinite(b.max[k])) << s.name;
  }
  ASSERT_GE(s.cameras.size(), 1u) << s.name;
  ASSERT_GE(s.materials.size(), 1u) << s.name;
  for (const Camera& c : s.cameras) {
    EXPECT_GT(c.nearPlane, 0.0f) << s.name << "/" << c.name;
    EXPECT_LT(c.nearPlane, c.farPlane) << s.name << "/" << c.name;
    EXPECT_GT(glm::length(c.target - c.position), 0.0f);
    EXPECT_EQ(s.findCamera(c.name), &c);
  }
  EXPECT_NEAR(glm::length(s.light.direction), 1.0f, 1e-4f);
  for (const Instance& i : s.instances) ASSERT_TRUE(i.mesh >= 0 && size_t(i.mesh) < s.meshes.size()) << s.name;
  for (const Mesh& m : s.meshes) {
    ASSERT_TRUE(m.material >= 0 && size_t(m.material) < s.materials.size()) << s.name;
    ASSERT_EQ(m.normals.size(), m.positions.size());
    ASSERT_EQ(m.uvs.size(), m.positions.size());
    for (uint32_t idx : m.indices) ASSERT_LT(idx, m.positions.size()) << s.name << "/" << m.name;
  }
  for (const Material& m : s.materials) {
    ASSERT_TRUE(m.baseColorTexture >= -1 && m.baseColorTexture < int(s.textures.size())) << s.name;
  }
  for (const CameraPath& p : s.paths) {
    ASSERT_GE(p.keys.size(), 2u);
    EXPECT_EQ(s.findPath(p.name), &p);
  }
}

TEST(SceneBuiltin, IdsListed) {
  const auto ids = builtinSceneIds(kAssets);
  ASSERT_FALSE(ids.empty());
  EXPECT_EQ(ids.front(), "basic");
  for (const char* id :
       {"columns", "dueling-frusta", "terrain", "thin-casters", "moving", "sponza", "engine", "tree"}) {
    EXPECT_NE(std::find(ids.begin(), ids.end(), id), ids.end()) << id;
  }
  EXPECT_TRUE(std::is_sorted(ids.begin() + 1, ids.end()));
}

TEST(SceneBuiltin, LocalScenesLoad) {
  for (const char* id : {"basic", "columns", "dueling-frusta", "terrain", "thin-casters", "moving"}) {
    SCOPED_TRACE(id);
    const Scene s = loadScene(id, kAssets);
    EXPECT_EQ(s.name, id);
    expectValidScene(s);
  }
  const Scene basic = loadScene("basic", kAssets);
  EXPECT_NE(basic.findCamera("default"), nullptr);
  EXPECT_NE(basic.findCamera("top"), nullptr);
  ASSERT_NE(basic.findPath("orbit"), nullptr);
  EXPECT_GE(basic.findPath("orbit")->keys.size(), 4u);
  EXPECT_FALSE(basic.hasMotion());
  EXPECT_GT(loadScene("terrain", kAssets).cameras[0].farPlane, 1999.0f);
}

// --- Small glTF files written by the tests -------------------------------------------------

void writeBinary(const std::string& name, const std::vector<uint8_t>& bytes) {
  std::ofstream(tempDir() / name, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), long(bytes.size()));
}

template <typename T>
void append(std::vector<uint8_t>& out, const std::vector<T>& v) {
  const size_t at = out.size();
  out.resize(at + v.size() * sizeof(T));
  std::memcpy(out.data() + at, v.data(), v.size() * sizeof(T));
}

// Two triangles (a quad in the XY plane): 4 positions + 6 ushort indices, or 6 positions when
// not indexed. `badIndex` puts vertex index 9 into the index buffer.
std::string writeQuadGltf(const std::string& stem, bool indexed, bool badIndex, bool writeBin,
                          const std::string& materialJson = "") {
  std::vector<uint8_t> bin;
  std::vector<float> pos = indexed ? std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}
                                   : std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
  append(bin, pos);
  const size_t posBytes = bin.size();
  std::vector<uint16_t> idx = {0, 1, 2, 0, 2, uint16_t(badIndex ? 9 : 3)};
  if (indexed) append(bin, idx);
  if (writeBin) writeBinary(stem + ".bin", bin);
  const size_t vcount = pos.size() / 3;
  std::string json = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
    "nodes":[{"mesh":0,"translation":[0,0,-2]}],
    "buffers":[{"uri":")" +
                     stem + R"(.bin","byteLength":)" + std::to_string(bin.size()) + R"(}],
    "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" +
                     std::to_string(posBytes) + "}";
  if (indexed) json += R"(,{"buffer":0,"byteOffset":)" + std::to_string(posBytes) + R"(,"byteLength":12})";
  json += R"(],"accessors":[{"bufferView":0,"componentType":5126,"count":)" + std::to_string(vcount) +
          R"(,"type":"VEC3","min":[0,0,0],"max":[1,1,0]})";
  if (indexed) json += R"(,{"bufferView":1,"componentType":5123,"count":6,"type":"SCALAR"})";
  json += R"(],"meshes":[{"name":"quad","primitives":[{"attributes":{"POSITION":0})";
  if (indexed) json += R"(,"indices":1)";
  if (!materialJson.empty()) json += R"(,"material":0)";
  json += "}]}]";
  if (!materialJson.empty()) json += "," + materialJson;
  json += "}";
  return writeFile(stem + ".gltf", json);
}

TEST(SceneGltf, NonIndexedGetsIndicesAndFlatNormals) {
  const std::string path = writeQuadGltf("nonindexed", false, false, true);
  const Scene s = loadScene(path, kAssets);
  expectValidScene(s);
  EXPECT_EQ(s.triangleCount(), 2u);
  ASSERT_EQ(s.instances.size(), 1u);
  const Mesh& m = s.meshes[s.instances[0].mesh];
  EXPECT_EQ(m.indices.size(), 6u);
  for (const auto& n : m.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
  // Node translation becomes the instance transform; the automatic camera frames it.
  EXPECT_NEAR(s.instances[0].transform[3].z, -2.0f, 1e-6f);
  EXPECT_NEAR(s.boundsAt(0).center().z, -2.0f, 1e-6f);
  EXPECT_NEAR(s.cameras[0].target.z, -2.0f, 1e-5f);
  EXPECT_NEAR(s.light.direction.x, glm::normalize(glm::vec3(-0.3f, -1, -0.2f)).x, 1e-5f);
}

TEST(SceneGltf, IndexedThroughSceneJsonWithTransform) {
  writeQuadGltf("indexed", true, false, true);
  const std::string path =
      writeFile("with_model.json", R"({"models":[{"file":"indexed.gltf","transform":{"translate":[10,0,0]}}]})");
  const Scene s = loadScene(path, kAssets);
  expectValidScene(s);
  EXPECT_EQ(s.triangleCount(), 2u);
  EXPECT_NEAR(s.boundsAt(0).min.x, 10.0f, 1e-5f);
  EXPECT_NEAR(s.boundsAt(0).min.z, -2.0f, 1e-5f);
}

TEST(SceneGltf, IndexOutOfRange) {
  const std::string path = writeQuadGltf("badindex", true, true, true);
  const std::string msg = loadError(path);
  EXPECT_EQ(msg.rfind(path, 0), 0u) << msg;
  EXPECT_NE(msg.find("index 9"), std::string::npos) << msg;
  EXPECT_NE(msg.find("out of range"), std::string::npos) << msg;
}

TEST(SceneGltf, MissingBinAndMissingTexture) {
  const std::string path = writeQuadGltf("nobin", true, false, false);
  const std::string msg = loadError(path);
  EXPECT_EQ(msg.rfind(path, 0), 0u) << msg;
  EXPECT_NE(msg.find("nobin.bin"), std::string::npos) << "tinygltf's error should name the buffer: " << msg;
  const std::string tex =
      writeQuadGltf("notex", true, false, true,
                    R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}},"alphaMode":"MASK"}],
         "textures":[{"source":0}],"images":[{"uri":"missing_texture.png"}])");
  const std::string tmsg = loadError(tex);
  EXPECT_NE(tmsg.find("missing_texture.png"), std::string::npos) << tmsg;
  EXPECT_NE(tmsg.find("could not be loaded"), std::string::npos) << tmsg;
  EXPECT_NE(loadError(writeFile("garbage.gltf", "not json")).find("cannot load glTF"), std::string::npos);
}

// glTF BLEND stays a 0.5 mask for depth maps (as before) and becomes a semi-transparent caster
// for deep shadow maps and the reference (Material::alphaBlend, scene_effects.h).
TEST(SceneGltf, BlendMaterialIsSemiTransparent) {
  const std::string path = writeQuadGltf("blend", true, false, true,
                                         R"("materials":[{"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,0.4]},)"
                                         R"("alphaMode":"BLEND"}])");
  const Scene s = loadScene(path, kAssets);
  const Material& m = s.materials[s.meshes[s.instances[0].mesh].material];
  EXPECT_TRUE(m.alphaBlend);
  EXPECT_TRUE(m.alphaMask);
  EXPECT_FLOAT_EQ(m.alphaCutoff, 0.5f);
  EXPECT_FLOAT_EQ(m.baseColor.a, 0.4f);
  EXPECT_TRUE(sceneEffects(s).semiTransparent);
  const std::string mask = writeQuadGltf("mask", true, false, true, R"("materials":[{"alphaMode":"MASK"}])");
  EXPECT_FALSE(sceneEffects(loadScene(mask, kAssets)).semiTransparent);
}

// --- The real third-party scenes, when the shared folder is present -------------------------

fs::path sharedScenes() { return fs::path(SHADOWLAB_SOURCE_DIR) / ".." / "shared" / "scenes-real"; }

bool maskTextureHasHoles(const Scene& s, const Material& m) {
  if (!m.alphaMask || m.baseColorTexture < 0) return false;
  const Texture& t = s.textures[m.baseColorTexture];
  EXPECT_EQ(t.rgba.size(), size_t(t.width) * size_t(t.height) * 4) << t.name;
  bool transparent = false, opaque = false;
  for (size_t i = 3; i < t.rgba.size(); i += 4) {
    transparent = transparent || t.rgba[i] <= 10;
    opaque = opaque || t.rgba[i] >= 245;
  }
  return transparent && opaque;
}

TEST(SceneRealGltf, SponzaHasAlphaMaskedTextures) {
  if (!fs::exists(sharedScenes())) GTEST_SKIP() << "shared/scenes-real not found: " << sharedScenes();
  const Scene s = loadScene("sponza", kAssets);
  expectValidScene(s);
  EXPECT_EQ(s.triangleCount(), 262087u);
  bool found = false;
  for (const Material& m : s.materials) found = found || maskTextureHasHoles(s, m);
  EXPECT_TRUE(found) << "no alpha-mask material with a texture that has holes";
}

TEST(SceneRealGltf, TreeHasLeafCardsAndEngineLoads) {
  if (!fs::exists(sharedScenes())) GTEST_SKIP() << "shared/scenes-real not found: " << sharedScenes();
  const Scene tree = loadScene((sharedScenes() / "tree-quaternius" / "CommonTree_1.gltf").string(), kAssets);
  expectValidScene(tree);
  EXPECT_EQ(tree.triangleCount(), 6265u);
  bool leaves = false;
  for (const Material& m : tree.materials) leaves = leaves || maskTextureHasHoles(tree, m);
  EXPECT_TRUE(leaves) << "no alpha-masked leaf-card material";
  expectValidScene(loadScene("tree", kAssets));
  const Scene engine = loadScene("engine", kAssets);
  expectValidScene(engine);
  EXPECT_GT(engine.triangleCount(), 121000u);
}

}  // namespace
}  // namespace sl
