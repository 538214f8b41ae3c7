// Strict JSON value reading for the scene loader (see json_reader.h).
#include "scene/json_reader.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdio>

namespace sl {

using nlohmann::json;

// json::dump() would print non-finite numbers as null.
std::string describeJson(const json& j) {
  std::string s;
  if (j.is_number()) {
    const double v = j.get<double>();
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
  }
  if (j.is_array()) {
    s = "[";
    for (size_t i = 0; i < j.size() && s.size() < 80; ++i) s += (i ? "," : "") + describeJson(j[i]);
    s += "]";
  } else {
    s = j.dump();
  }
  if (s.size() > 80) s = s.substr(0, 77) + "...";
  return s;
}

void JsonReader::fail(const std::string& where, const std::string& what) const {
  throw SceneError(file_ + ": " + (where.empty() ? "" : where + ": ") + what);
}

void JsonReader::expected(const std::string& where, const std::string& what, const json& got) const {
  fail(where, "expected " + what + ", got " + describeJson(got));
}

void JsonReader::checkObject(const json& j, const std::string& where) const {
  if (!j.is_object()) expected(where, "an object", j);
}

// Rejects keys outside `allowed`, listing the allowed ones so typos are easy to fix.
void JsonReader::checkKeys(const json& j, const std::string& where, const std::vector<std::string>& allowed) const {
  checkObject(j, where);
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool known = false;
    for (const auto& a : allowed) known = known || a == it.key();
    if (!known) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      fail(where.empty() ? it.key() : where + "." + it.key(), "unknown key '" + it.key() + "' (allowed: " + list + ")");
    }
  }
}

const nlohmann::json* JsonReader::find(const json& j, const char* key) {
  auto it = j.find(key);
  return it == j.end() ? nullptr : &*it;
}

// Values are stored as float, so "finite" means finite as a float (1e300 is not).
bool JsonReader::finiteNumber(const json& j) {
  return j.is_number() && std::isfinite(j.get<double>()) && std::isfinite(float(j.get<double>()));
}

double JsonReader::number(const json& j, const std::string& where) const {
  if (!finiteNumber(j)) expected(where, "a finite number", j);
  return j.get<double>();
}

float JsonReader::positive(const json& j, const std::string& where) const {
  if (!finiteNumber(j) || !(j.get<double>() > 0.0)) {
    expected(where, "a positive finite number", j);
  }
  return float(j.get<double>());
}

int JsonReader::integer(const json& j, const std::string& where, int lo, int hi) const {
  const std::string what = "an integer in [" + std::to_string(lo) + "," + std::to_string(hi) + "]";
  if (!j.is_number() || !std::isfinite(j.get<double>())) expected(where, what, j);
  const double v = j.get<double>();
  if (v != std::floor(v) || v < lo || v > hi) expected(where, what, j);
  return int(v);
}

bool JsonReader::boolean(const json& j, const std::string& where) const {
  if (!j.is_boolean()) expected(where, "true or false", j);
  return j.get<bool>();
}

std::string JsonReader::string(const json& j, const std::string& where) const {
  if (!j.is_string()) expected(where, "a string", j);
  return j.get<std::string>();
}

// `n` finite numbers, optionally all > 0.
std::vector<float> JsonReader::numbers(const json& j, const std::string& where, size_t n, bool positiveOnly) const {
  const std::string what = std::to_string(n) + (positiveOnly ? " positive" : "") + " finite numbers";
  if (!j.is_array() || j.size() != n) expected(where, what, j);
  std::vector<float> out;
  for (const json& e : j) {
    if (!e.is_number()) expected(where, what, j);
    const double v = e.get<double>();
    if (!std::isfinite(v) || (positiveOnly && !(v > 0.0)) || !std::isfinite(float(v))) expected(where, what, j);
    out.push_back(float(v));
  }
  return out;
}

glm::vec3 JsonReader::vec3(const json& j, const std::string& where, bool positiveOnly) const {
  const auto v = numbers(j, where, 3, positiveOnly);
  return {v[0], v[1], v[2]};
}

glm::vec3 JsonReader::nonZeroVec3(const json& j, const std::string& where) const {
  const glm::vec3 v = vec3(j, where);
  if (!(glm::length(v) > 1e-12f)) expected(where, "a non-zero vector", j);
  return v;
}

// {"translate","rotate_deg","scale"} as T * Rz * Ry * Rx * S, or {"matrix": 16 column-major}.
glm::mat4 JsonReader::transform(const json& j, const std::string& where) const {
  checkKeys(j, where, {"translate", "rotate_deg", "scale", "matrix"});
  if (const json* m = find(j, "matrix")) {
    if (j.size() != 1) fail(where, "'matrix' cannot be combined with translate/rotate_deg/scale");
    const auto v = numbers(*m, where + ".matrix", 16, false);
    const glm::mat4 mat = glm::make_mat4(v.data());
    if (!(std::fabs(glm::determinant(glm::mat3(mat))) > 1e-20f)) fail(where + ".matrix", "matrix is singular");
    return mat;
  }
  glm::mat4 t(1.0f);
  if (const json* v = find(j, "translate")) t = glm::translate(t, vec3(*v, where + ".translate"));
  if (const json* v = find(j, "rotate_deg")) {
    const glm::vec3 r = glm::radians(vec3(*v, where + ".rotate_deg"));
    t = glm::rotate(t, r.z, {0, 0, 1});
    t = glm::rotate(t, r.y, {0, 1, 0});
    t = glm::rotate(t, r.x, {1, 0, 0});
  }
  if (const json* v = find(j, "scale")) {
    glm::vec3 s;
    if (v->is_number())
      s = glm::vec3(number(*v, where + ".scale"));
    else
      s = vec3(*v, where + ".scale");
    if (s.x == 0.0f || s.y == 0.0f || s.z == 0.0f) expected(where + ".scale", "non-zero scale factors", *v);
    t = glm::scale(t, s);
  }
  return t;
}

}  // namespace sl
