// loadScene: the JSON scene format (docs/scene-format.md) and bare glTF files.
// Validation is strict on purpose: a typo in a key or a degenerate value must be reported with
// the file and the JSON location instead of silently producing a different scene.
#include "scene/gltf_loader.h"
#include "scene/scene_json_media.h"
#include "scene/json_reader.h"
#include "scene/mesh_ops.h"
#include "scene/scene.h"
#include "scene/shapes.h"

#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#ifndef SHADOWLAB_SOURCE_DIR
#define SHADOWLAB_SOURCE_DIR "."
#endif

namespace sl {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const glm::vec3 kAutoLightDirection = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f));

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw SceneError(path + ": cannot read file");
  return ss.str();
}

std::string resolveModelPath(const std::string& file, const fs::path& sceneDir) {
  const std::string prefix = "$SHARED/";
  if (file.compare(0, prefix.size(), prefix) == 0) {
    const char* env = std::getenv("SHADOWLAB_SHARED");
    const fs::path root = (env && *env) ? fs::path(env) : fs::path(SHADOWLAB_SOURCE_DIR) / ".." / "shared";
    return (root / file.substr(prefix.size())).lexically_normal().string();
  }
  const fs::path p(file);
  if (p.is_absolute()) return p.string();
  return (sceneDir / p).lexically_normal().string();
}

Motion parseMotion(const JsonReader& r, const json& j, const std::string& where, glm::vec3* pivot) {
  r.checkObject(j, where);
  const json* type = JsonReader::find(j, "type");
  if (!type) r.fail(where, "missing 'type' (oscillate, rotate or none)");
  const std::string t = r.string(*type, where + ".type");
  Motion m;
  if (t == "none") {
    r.checkKeys(j, where, {"type"});
    return m;
  }
  if (t == "oscillate") {
    r.checkKeys(j, where, {"type", "vector", "period"});
    m.type = Motion::Type::Oscillate;
    const json* v = JsonReader::find(j, "vector");
    if (!v) r.fail(where, "missing 'vector' (displacement amplitude)");
    m.vector = r.vec3(*v, where + ".vector");
  } else if (t == "rotate") {
    r.checkKeys(j, where, {"type", "axis", "pivot", "period"});
    m.type = Motion::Type::Rotate;
    const json* a = JsonReader::find(j, "axis");
    m.vector = a ? glm::normalize(r.nonZeroVec3(*a, where + ".axis")) : glm::vec3(0, 1, 0);
    if (const json* p = JsonReader::find(j, "pivot")) *pivot = r.vec3(*p, where + ".pivot");
  } else {
    r.fail(where + ".type", "unknown motion type '" + t + "' (expected oscillate, rotate or none)");
  }
  if (const json* p = JsonReader::find(j, "period")) m.period = r.positive(*p, where + ".period");
  return m;
}

// Moves a mesh into another frame (used to bake an object's placement relative to a pivot).
void transformMesh(Mesh& mesh, const glm::mat4& m) {
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(m)));
  for (auto& p : mesh.positions) p = glm::vec3(m * glm::vec4(p, 1.0f));
  for (auto& n : mesh.normals) n = glm::normalize(normalMatrix * n);
}

// The mesh of an object's `shape`, its keys checked against that shape's.
Mesh parseShapeMesh(const JsonReader& r, const json& j, const std::string& where, const std::string& shape) {
  std::vector<std::string> keys = {"name", "shape", "color", "opacity", "transform", "motion", "double_sided"};
  Mesh mesh;
  if (shape == "plane") {
    keys.insert(keys.end(), {"size", "subdivisions"});
    r.checkKeys(j, where, keys);
    const json* s = JsonReader::find(j, "size");
    if (!s) r.fail(where, "missing 'size' ([x, z])");
    const auto size = r.numbers(*s, where + ".size", 2, true);
    const json* d = JsonReader::find(j, "subdivisions");
    mesh = makePlane(size[0], size[1], d ? r.integer(*d, where + ".subdivisions", 1, 1024) : 16);
  } else if (shape == "box") {
    keys.insert(keys.end(), {"size"});
    r.checkKeys(j, where, keys);
    const json* s = JsonReader::find(j, "size");
    mesh = makeBox(s ? r.vec3(*s, where + ".size", true) : glm::vec3(1.0f));
  } else if (shape == "sphere") {
    keys.insert(keys.end(), {"radius", "segments"});
    r.checkKeys(j, where, keys);
    const json* rad = JsonReader::find(j, "radius");
    const json* seg = JsonReader::find(j, "segments");
    mesh = makeSphere(rad ? r.positive(*rad, where + ".radius") : 0.5f,
                      seg ? r.integer(*seg, where + ".segments", 3, 1024) : 32);
  } else if (shape == "cylinder") {
    keys.insert(keys.end(), {"radius", "height", "segments", "capped"});
    r.checkKeys(j, where, keys);
    const json* rad = JsonReader::find(j, "radius");
    const json* h = JsonReader::find(j, "height");
    const json* seg = JsonReader::find(j, "segments");
    const json* cap = JsonReader::find(j, "capped");
    mesh = makeCylinder(rad ? r.positive(*rad, where + ".radius") : 0.5f, h ? r.positive(*h, where + ".height") : 1.0f,
                        seg ? r.integer(*seg, where + ".segments", 3, 1024) : 24,
                        cap ? r.boolean(*cap, where + ".capped") : true);
  } else {
    r.fail(where + ".shape", "unknown shape '" + shape + "' (expected plane, box, sphere or cylinder)");
  }
  return mesh;
}

// An object's material: colour, double-sidedness, and opacity (a semi-transparent caster).
Material parseObjectMaterial(const JsonReader& r, const json& j, const std::string& where) {
  Material mat;
  if (const json* c = JsonReader::find(j, "color")) {
    const size_t n = c->is_array() ? c->size() : 0;
    if (n != 3 && n != 4) r.expected(where + ".color", "3 or 4 numbers in [0,1]", *c);
    const auto v = r.numbers(*c, where + ".color", n, false);
    for (float x : v) {
      if (x < 0.0f || x > 1.0f) r.expected(where + ".color", "3 or 4 numbers in [0,1]", *c);
    }
    mat.baseColor = glm::vec4(v[0], v[1], v[2], n == 4 ? v[3] : 1.0f);
  }
  if (const json* d = JsonReader::find(j, "double_sided")) mat.doubleSided = r.boolean(*d, where + ".double_sided");
  if (const json* o = JsonReader::find(j, "opacity")) {
    // A semi-transparent caster (a sheet of tinted glass, a curtain): light through it is
    // attenuated by `opacity` (deep shadow maps, the reference); other techniques cast it opaque.
    const double a = r.number(*o, where + ".opacity");
    if (!(a >= 0.0 && a <= 1.0)) r.expected(where + ".opacity", "a number in [0,1]", *o);
    mat.baseColor.a = float(a);
    mat.alphaBlend = true;
  }
  return mat;
}

void parseObject(const JsonReader& r, const json& j, const std::string& where, Scene& scene) {
  r.checkObject(j, where);
  const json* shapeJ = JsonReader::find(j, "shape");
  if (!shapeJ) r.fail(where, "missing 'shape' (plane, box, sphere or cylinder)");
  const std::string shape = r.string(*shapeJ, where + ".shape");
  Mesh mesh = parseShapeMesh(r, j, where, shape);
  const Material mat = parseObjectMaterial(r, j, where);

  Instance inst;
  const json* nameJ = JsonReader::find(j, "name");
  inst.name = nameJ ? r.string(*nameJ, where + ".name") : shape + std::to_string(scene.instances.size());
  mesh.name = inst.name;
  if (const json* t = JsonReader::find(j, "transform")) inst.transform = r.transform(*t, where + ".transform");
  // A negative scale mirrors the shape; without this its triangles would face inward for
  // culling, the second-depth map and gl_FrontFacing. (Baking it below keeps the mirror.)
  if (mirrors(inst.transform)) reverseWinding(mesh);
  if (const json* m = JsonReader::find(j, "motion")) {
    glm::vec3 pivot(0.0f);
    bool hasPivot = JsonReader::find(*m, "pivot") != nullptr;
    inst.motion = parseMotion(r, *m, where + ".motion", &pivot);
    if (hasPivot) {
      // Motion::at applies in object space, so rotating about a world pivot means making the
      // pivot the object-space origin: bake the placement into the mesh, relative to the pivot.
      const glm::mat4 toPivot = glm::translate(glm::mat4(1.0f), pivot);
      transformMesh(mesh, glm::inverse(toPivot) * inst.transform);
      inst.transform = toPivot;
    }
  }
  scene.materials.push_back(mat);
  mesh.material = int(scene.materials.size() - 1);
  scene.meshes.push_back(std::move(mesh));
  inst.mesh = int(scene.meshes.size() - 1);
  scene.instances.push_back(inst);
}

Light parseLight(const JsonReader& r, const json& j, const std::string& where) {
  if (!j.is_object()) r.expected(where, "a light object", j);
  r.checkKeys(j, where, {"type", "direction", "position", "fov_deg", "radius", "range", "color", "shadow"});
  Light l;
  l.direction = kAutoLightDirection;
  if (const json* t = JsonReader::find(j, "type")) {
    const std::string type = r.string(*t, where + ".type");
    if (type == "spot")
      l.type = Light::Type::Spot;
    else if (type == "point")
      l.type = Light::Type::Point;
    else if (type != "directional")
      r.fail(where + ".type", "unknown light type '" + type + "' (expected directional, spot or point)");
  }
  if (l.type == Light::Type::Point && !JsonReader::find(j, "position"))
    r.fail(where + ".position", "a point light needs a position");
  if (const json* d = JsonReader::find(j, "direction")) {
    const glm::vec3 v = r.vec3(*d, where + ".direction");
    if (!(glm::length(v) > 1e-12f)) r.fail(where + ".direction", "zero-length light direction");
    l.direction = glm::normalize(v);
  }
  if (const json* p = JsonReader::find(j, "position")) l.position = r.vec3(*p, where + ".position");
  if (const json* f = JsonReader::find(j, "fov_deg")) {
    l.fovDeg = float(r.number(*f, where + ".fov_deg"));
    if (!(l.fovDeg > 0.0f && l.fovDeg < 180.0f))
      r.expected(where + ".fov_deg", "a field of view in (0,180) degrees", *f);
  }
  if (const json* rad = JsonReader::find(j, "radius")) {
    l.radius = float(r.number(*rad, where + ".radius"));
    // A double beyond float range becomes Inf here: the soft-shadow filters would turn it into NaN.
    if (!(l.radius >= 0.0f) || !std::isfinite(l.radius)) r.expected(where + ".radius", "a finite radius >= 0", *rad);
  }
  if (const json* range = JsonReader::find(j, "range")) {
    if (l.type != Light::Type::Point) r.fail(where + ".range", "only a point light has a range");
    l.range = float(r.number(*range, where + ".range"));
    if (!(l.range > 0.0f) || !std::isfinite(l.range)) r.expected(where + ".range", "a finite range > 0", *range);
  }
  if (const json* s = JsonReader::find(j, "shadow")) l.shadow = r.boolean(*s, where + ".shadow");
  if (const json* c = JsonReader::find(j, "color")) {
    l.color = r.vec3(*c, where + ".color");
    if (glm::any(glm::lessThan(l.color, glm::vec3(0.0f)))) r.expected(where + ".color", "3 non-negative numbers", *c);
  }
  return l;
}

// The scene's lights from "light": {...} or "lights": [...] (every entry checked); false when the
// file gives neither (finish() then places the automatic sun). The first shadowed light of the
// list becomes Scene::light, the rest Scene::otherLights in order; a list where no light casts
// shadows is refused: every technique shadows at least one light.
bool parseLights(const JsonReader& r, const json& root, Scene& scene) {
  const json* single = JsonReader::find(root, "light");
  const json* list = JsonReader::find(root, "lights");
  if (single && list) r.fail("lights", "give either 'light' or 'lights', not both");
  if (single) {
    scene.light = parseLight(r, *single, "light");
    if (!scene.light.shadow) r.fail("light.shadow", "the scene's only light must cast shadows");
  }
  if (!list) return single != nullptr;
  if (!list->is_array()) r.expected("lights", "an array of light objects", *list);
  if (list->empty()) r.fail("lights", "an empty light list (leave it out for the automatic sun)");
  if (list->size() > size_t(kMaxSceneLights))
    r.fail("lights", std::to_string(list->size()) + " lights (at most " + std::to_string(kMaxSceneLights) + ")");
  std::vector<Light> parsed;
  for (size_t i = 0; i < list->size(); ++i)
    parsed.push_back(parseLight(r, (*list)[i], "lights[" + std::to_string(i) + "]"));
  const auto primary = std::find_if(parsed.begin(), parsed.end(), [](const Light& l) { return l.shadow; });
  if (primary == parsed.end()) r.fail("lights", "no light casts shadows (at least one needs \"shadow\": true)");
  scene.light = *primary;
  scene.otherLights.clear();
  for (auto it = parsed.begin(); it != parsed.end(); ++it)
    if (it != primary) scene.otherLights.push_back(*it);
  return true;
}

void checkCamera(const JsonReader& r, const Camera& c, const std::string& where) {
  if (!(c.fovDeg > 0.0f && c.fovDeg < 180.0f)) r.fail(where + ".fov_deg", "field of view must be in (0,180) degrees");
  if (!(c.nearPlane > 0.0f)) r.fail(where + ".near", "near plane must be > 0");
  if (!(c.nearPlane < c.farPlane)) r.fail(where + ".far", "near must be < far");
  const glm::vec3 view = c.target - c.position;
  if (!(glm::length(view) > 1e-6f)) r.fail(where, "camera position equals target");
  if (!(glm::length(glm::cross(glm::normalize(view), c.up)) > 1e-4f)) {
    r.fail(where + ".up", "up vector is parallel to the view direction");
  }
}

Camera parseCamera(const JsonReader& r, const json& j, const std::string& where, size_t index) {
  r.checkKeys(j, where, {"name", "position", "target", "up", "fov_deg", "near", "far"});
  Camera c;
  const json* n = JsonReader::find(j, "name");
  c.name = n ? r.string(*n, where + ".name") : (index == 0 ? "default" : "camera" + std::to_string(index));
  const json* p = JsonReader::find(j, "position");
  const json* t = JsonReader::find(j, "target");
  if (!p || !t) r.fail(where, "a camera needs 'position' and 'target'");
  c.position = r.vec3(*p, where + ".position");
  c.target = r.vec3(*t, where + ".target");
  if (const json* u = JsonReader::find(j, "up")) c.up = glm::normalize(r.nonZeroVec3(*u, where + ".up"));
  if (const json* f = JsonReader::find(j, "fov_deg")) c.fovDeg = float(r.number(*f, where + ".fov_deg"));
  if (const json* v = JsonReader::find(j, "near")) c.nearPlane = float(r.number(*v, where + ".near"));
  if (const json* v = JsonReader::find(j, "far")) c.farPlane = float(r.number(*v, where + ".far"));
  checkCamera(r, c, where);
  return c;
}

CameraPath parsePath(const JsonReader& r, const json& j, const std::string& where, size_t index) {
  r.checkKeys(j, where, {"name", "keys"});
  CameraPath path;
  const json* n = JsonReader::find(j, "name");
  path.name = n ? r.string(*n, where + ".name") : "path" + std::to_string(index);
  const json* keys = JsonReader::find(j, "keys");
  if (!keys || !keys->is_array() || keys->size() < 2) {
    r.fail(where + ".keys", "a path needs at least 2 keys");
  }
  for (size_t i = 0; i < keys->size(); ++i) {
    const std::string kw = where + ".keys[" + std::to_string(i) + "]";
    const json& k = (*keys)[i];
    r.checkKeys(k, kw, {"time", "position", "target"});
    const json* t = JsonReader::find(k, "time");
    const json* p = JsonReader::find(k, "position");
    const json* g = JsonReader::find(k, "target");
    if (!t || !p || !g) r.fail(kw, "a key needs 'time', 'position' and 'target'");
    CameraKeyframe key;
    key.time = float(r.number(*t, kw + ".time"));
    key.position = r.vec3(*p, kw + ".position");
    key.target = r.vec3(*g, kw + ".target");
    if (i == 0 && key.time < 0.0f) r.fail(kw + ".time", "times must start at >= 0");
    if (i > 0 && !(key.time > path.keys.back().time)) r.fail(kw + ".time", "key times must be strictly increasing");
    if (!(glm::length(key.target - key.position) > 1e-6f)) r.fail(kw, "camera position equals target");
    path.keys.push_back(key);
  }
  return path;
}

// A camera that sees the whole of `b`, looking at its centre from the front, right and above.
Camera frameBounds(const Bounds& b) {
  Camera c;
  c.name = "default";
  const float radius = std::max(0.5f * glm::length(b.extent()), 1e-3f);
  c.fovDeg = 60.0f;
  const float distance = 1.5f * radius / std::tan(glm::radians(c.fovDeg) * 0.5f);
  c.target = b.center();
  c.position = c.target + glm::normalize(glm::vec3(0.6f, 0.45f, 1.0f)) * distance;
  c.nearPlane = radius / 1000.0f;
  c.farPlane = distance + 2.0f * radius;
  return c;
}

// Checks shared by JSON and glTF scenes, and the automatic parts.
void finish(Scene& scene, bool haveLight) {
  if (scene.triangleCount() == 0) throw SceneError(scene.sourcePath + ": scene has no triangles (empty scene)");
  const Bounds b = scene.boundsAt(0.0);
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(b.min[k]) || !std::isfinite(b.max[k]) || std::fabs(b.min[k]) > 1e29f ||
        std::fabs(b.max[k]) > 1e29f) {
      throw SceneError(scene.sourcePath + ": scene bounds are not finite");
    }
  }
  if (!haveLight) {
    scene.light = Light{};
    scene.light.direction = kAutoLightDirection;
    scene.light.position = b.center() - kAutoLightDirection * glm::length(b.extent());
  }
  if (scene.cameras.empty()) scene.cameras.push_back(frameBounds(b));
  if (scene.materials.empty()) scene.materials.push_back(Material{});
}

// "models": glTF files placed by their transform; a file's own error is reported under the
// entry's field (with how $SHARED/ resolves where the path uses it).
void appendModels(const JsonReader& r, const json& models, const fs::path& dir, Scene& scene) {
  for (size_t i = 0; i < models.size(); ++i) {
    const std::string where = "models[" + std::to_string(i) + "]";
    const json& m = models[i];
    r.checkKeys(m, where, {"file", "transform"});
    const json* f = JsonReader::find(m, "file");
    if (!f) r.fail(where, "missing 'file'");
    const std::string given = r.string(*f, where + ".file");
    const std::string file = resolveModelPath(given, dir);
    const json* t = JsonReader::find(m, "transform");
    const glm::mat4 xf = t ? r.transform(*t, where + ".transform") : glm::mat4(1.0f);
    try {
      appendGltf(scene, file, xf);
    } catch (const SceneError& e) {
      const bool shared = given.compare(0, 8, "$SHARED/") == 0;
      r.fail(where + ".file", e.what() + std::string(shared ? " ($SHARED/ is resolved through the "
                                                              "SHADOWLAB_SHARED environment variable, "
                                                              "else <source dir>/../shared)"
                                                            : ""));
    }
  }
}

Scene loadJsonScene(const std::string& path) {
  const std::string text = readFile(path);
  JsonReader r(path);
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    r.fail("", "malformed JSON at byte " + std::to_string(e.byte) + ": " + e.what());
  } catch (const json::exception& e) {
    // nlohmann reports literals like 1e999 this way (out_of_range 406) instead of storing inf.
    r.fail("", "malformed JSON (numbers must be finite): " + std::string(e.what()));
  }
  r.checkKeys(root, "",
              {"name", "description", "models", "objects", "hair", "volumes", "light", "lights", "cameras", "paths"});
  Scene scene;
  scene.sourcePath = path;
  const json* name = JsonReader::find(root, "name");
  scene.name = name ? r.string(*name, "name") : fs::path(path).stem().string();
  if (const json* d = JsonReader::find(root, "description")) r.string(*d, "description");

  auto array = [&](const char* key) -> const json* {
    const json* a = JsonReader::find(root, key);
    if (a && !a->is_array()) r.expected(key, "an array", *a);
    return a;
  };
  if (const json* models = array("models")) appendModels(r, *models, fs::path(path).parent_path(), scene);
  if (const json* objects = array("objects")) {
    for (size_t i = 0; i < objects->size(); ++i) {
      parseObject(r, (*objects)[i], "objects[" + std::to_string(i) + "]", scene);
    }
  }
  // Hair grows on objects (and models) declared above, whatever the key order in the file.
  if (const json* hair = array("hair")) {
    for (size_t i = 0; i < hair->size(); ++i) parseHair(r, (*hair)[i], "hair[" + std::to_string(i) + "]", scene);
  }
  if (const json* volumes = array("volumes")) {
    for (size_t i = 0; i < volumes->size(); ++i)
      parseVolume(r, (*volumes)[i], "volumes[" + std::to_string(i) + "]", scene);
  }
  const bool haveLight = parseLights(r, root, scene);
  std::set<std::string> names;
  if (const json* cams = array("cameras")) {
    for (size_t i = 0; i < cams->size(); ++i) {
      const std::string where = "cameras[" + std::to_string(i) + "]";
      scene.cameras.push_back(parseCamera(r, (*cams)[i], where, i));
      if (!names.insert(scene.cameras.back().name).second)
        r.fail(where + ".name", "duplicate camera name '" + scene.cameras.back().name + "'");
    }
  }
  names.clear();
  if (const json* paths = array("paths")) {
    for (size_t i = 0; i < paths->size(); ++i) {
      const std::string where = "paths[" + std::to_string(i) + "]";
      scene.paths.push_back(parsePath(r, (*paths)[i], where, i));
      if (!names.insert(scene.paths.back().name).second)
        r.fail(where + ".name", "duplicate path name '" + scene.paths.back().name + "'");
    }
  }
  finish(scene, haveLight);
  return scene;
}

Scene loadGltfScene(const std::string& path) {
  Scene scene;
  scene.sourcePath = path;
  scene.name = fs::path(path).stem().string();
  appendGltf(scene, path, glm::mat4(1.0f));
  finish(scene, false);
  return scene;
}

}  // namespace

Scene loadScene(const std::string& idOrPath, const std::string& assetsDir) {
  const fs::path p(idOrPath);
  std::string path = idOrPath;
  if (idOrPath.find('/') == std::string::npos && idOrPath.find('\\') == std::string::npos && !p.has_extension()) {
    path = (fs::path(assetsDir) / "scenes" / (idOrPath + ".json")).string();
    std::error_code ec;
    if (idOrPath.empty() || !fs::is_regular_file(path, ec)) {
      std::string ids;
      for (const auto& id : builtinSceneIds(assetsDir)) ids += (ids.empty() ? "" : ", ") + id;
      throw SceneError(path + ": unknown builtin scene id '" + idOrPath +
                       "' (available: " + (ids.empty() ? "none found in " + assetsDir + "/scenes" : ids) + ")");
    }
  }
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  try {
    if (ext == ".json") return loadJsonScene(path);
    if (ext == ".gltf" || ext == ".glb") return loadGltfScene(path);
  } catch (const SceneError&) {
    throw;
  } catch (const json::exception& e) {
    // Safety net: every access above checks types first, but never let a library exception
    // escape as something other than a SceneError.
    throw SceneError(path + ": JSON error: " + e.what());
  } catch (const std::exception& e) {
    throw SceneError(path + ": " + e.what());
  }
  throw SceneError(path + ": unsupported scene file type '" + ext + "' (expected .json, .gltf or .glb)");
}

}  // namespace sl
