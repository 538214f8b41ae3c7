// Strict reading of JSON values for the scene loader: every failure names the file, the JSON
// location and what was expected, with a short rendering of what was found.
#pragma once

#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace sl {

// Compact, bounded rendering of a JSON value for error messages (non-finite numbers spelled out).
std::string describeJson(const nlohmann::json& j);

class JsonReader {
 public:
  using json = nlohmann::json;
  explicit JsonReader(std::string file) : file_(std::move(file)) {}

  // Throw SceneError("FILE: WHERE: WHAT").
  [[noreturn]] void fail(const std::string& where, const std::string& what) const;
  [[noreturn]] void expected(const std::string& where, const std::string& what, const json& got) const;

  void checkObject(const json& j, const std::string& where) const;
  // Rejects keys outside `allowed`, listing the allowed ones so typos are easy to fix.
  void checkKeys(const json& j, const std::string& where, const std::vector<std::string>& allowed) const;
  static const json* find(const json& j, const char* key);

  // Values are stored as float, so "finite" means finite as a float (1e300 is not).
  static bool finiteNumber(const json& j);
  double number(const json& j, const std::string& where) const;
  float positive(const json& j, const std::string& where) const;
  int integer(const json& j, const std::string& where, int lo, int hi) const;
  bool boolean(const json& j, const std::string& where) const;
  std::string string(const json& j, const std::string& where) const;
  // `n` finite numbers, optionally all > 0.
  std::vector<float> numbers(const json& j, const std::string& where, size_t n, bool positiveOnly) const;
  glm::vec3 vec3(const json& j, const std::string& where, bool positiveOnly = false) const;
  glm::vec3 nonZeroVec3(const json& j, const std::string& where) const;
  // {"translate","rotate_deg","scale"} as T * Rz * Ry * Rx * S, or {"matrix": 16 column-major}.
  glm::mat4 transform(const json& j, const std::string& where) const;

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

}  // namespace sl
