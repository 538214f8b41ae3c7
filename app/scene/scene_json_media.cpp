#include "scene/scene_json_media.h"

#include "scene/hair.h"

namespace sl {

using nlohmann::json;

void parseHair(const JsonReader& r, const json& j, const std::string& where, Scene& scene) {
  r.checkObject(j, where);
  r.checkKeys(
      j, where,
      {"name", "on", "count", "length", "curl", "turns", "width", "opacity", "droop", "segments", "color", "seed"});
  HairSpec h;
  const json* on = JsonReader::find(j, "on");
  if (!on) r.fail(where, "missing 'on' (the name of the object the strands grow from)");
  h.on = r.string(*on, where + ".on");
  if (const json* n = JsonReader::find(j, "name")) h.name = r.string(*n, where + ".name");
  if (const json* c = JsonReader::find(j, "count")) h.count = r.integer(*c, where + ".count", 0, 200000);
  if (const json* l = JsonReader::find(j, "length")) h.length = r.positive(*l, where + ".length");
  if (const json* w = JsonReader::find(j, "width")) h.width = r.positive(*w, where + ".width");
  auto range = [&](const char* key, float lo, float hi, float& out) {
    const json* v = JsonReader::find(j, key);
    if (!v) return;
    const double x = r.number(*v, where + "." + key);
    if (!(x >= lo && x <= hi))
      r.expected(where + "." + key, "a number in [" + describeJson(lo) + ", " + describeJson(hi) + "]", *v);
    out = float(x);
  };
  range("opacity", 0.0f, 1.0f, h.opacity);
  range("curl", 0.0f, 1e3f, h.curl);
  range("turns", 0.0f, 100.0f, h.turns);
  range("droop", 0.0f, 10.0f, h.droop);
  if (const json* s = JsonReader::find(j, "segments")) h.segments = r.integer(*s, where + ".segments", 1, 64);
  if (const json* s = JsonReader::find(j, "seed")) h.seed = uint32_t(r.integer(*s, where + ".seed", 0, 1 << 30));
  if (const json* c = JsonReader::find(j, "color")) {
    h.color = r.vec3(*c, where + ".color");
    if (glm::any(glm::lessThan(h.color, glm::vec3(0.0f))) || glm::any(glm::greaterThan(h.color, glm::vec3(1.0f))))
      r.expected(where + ".color", "3 numbers in [0,1]", *c);
  }
  appendHair(scene, h, where);
}

void parseVolume(const JsonReader& r, const json& j, const std::string& where, Scene& scene) {
  r.checkObject(j, where);
  const json* shapeJ = JsonReader::find(j, "shape");
  if (!shapeJ) r.fail(where, "missing 'shape' (box or sphere)");
  const std::string shape = r.string(*shapeJ, where + ".shape");
  Volume v;
  std::vector<std::string> keys = {"name", "shape", "center", "extinction", "noise", "noise_scale", "octaves", "seed"};
  if (shape == "box") {
    keys.push_back("size");
    r.checkKeys(j, where, keys);
    const json* s = JsonReader::find(j, "size");
    if (!s) r.fail(where, "missing 'size' ([x, y, z])");
    v.halfSize = 0.5f * r.vec3(*s, where + ".size", true);
  } else if (shape == "sphere") {
    keys.push_back("radius");
    r.checkKeys(j, where, keys);
    v.shape = Volume::Shape::Sphere;
    const json* rad = JsonReader::find(j, "radius");
    if (!rad) r.fail(where, "missing 'radius'");
    v.halfSize = glm::vec3(r.positive(*rad, where + ".radius"));
  } else {
    r.fail(where + ".shape", "unknown volume shape '" + shape + "' (expected box or sphere)");
  }
  const json* n = JsonReader::find(j, "name");
  v.name = n ? r.string(*n, where + ".name") : "volume" + std::to_string(scene.volumes.size());
  if (const json* c = JsonReader::find(j, "center")) v.center = r.vec3(*c, where + ".center");
  const json* e = JsonReader::find(j, "extinction");
  if (!e) r.fail(where, "missing 'extinction' (sigma_t per world unit, >= 0)");
  v.extinction = float(r.number(*e, where + ".extinction"));
  if (!(v.extinction >= 0.0f && v.extinction <= 1e6f))
    r.expected(where + ".extinction", "an extinction coefficient in [0, 1e6] per world unit", *e);
  if (const json* x = JsonReader::find(j, "noise")) {
    v.noise = float(r.number(*x, where + ".noise"));
    if (!(v.noise >= 0.0f && v.noise <= 1.0f)) r.expected(where + ".noise", "a number in [0,1]", *x);
  }
  if (const json* x = JsonReader::find(j, "noise_scale")) v.noiseScale = r.positive(*x, where + ".noise_scale");
  if (const json* x = JsonReader::find(j, "octaves")) v.octaves = r.integer(*x, where + ".octaves", 1, 8);
  if (const json* x = JsonReader::find(j, "seed")) v.seed = uint32_t(r.integer(*x, where + ".seed", 0, (1 << 24) - 1));  // exact as a GLSL float
  if (scene.volumes.size() >= 4) r.fail(where, "at most 4 volumes per scene");
  scene.volumes.push_back(v);
}

}  // namespace sl
