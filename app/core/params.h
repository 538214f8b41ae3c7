// Parameters are declared once (ParamDecl) and everything else is derived from that
// declaration: the ImGui panel, `--set key=value`, `shadowlab list`, JSON presets, bench
// sweeps and the shader uniforms (key "pcf.radius" becomes uniform `u_pcf_radius`).
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace sl {

class ParamError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class ParamType { Float, Int, Bool, Enum };

struct ParamDecl {
  std::string key;  // dotted, e.g. "bias.slope"
  ParamType type = ParamType::Float;
  double min = 0, max = 1;           // Float/Int range (inclusive)
  double defaultValue = 0;           // Enum: index into choices; Bool: 0/1
  std::string unit;                  // "texels", "world units", "" ...
  std::string help;                  // one line, shown as tooltip and in `shadowlab list`
  std::vector<std::string> choices;  // Enum only
  bool logScale = false;             // UI hint for wide ranges
};

const char* paramTypeName(ParamType t);
std::string describeRange(const ParamDecl& d);              // "64..8192", "none|constant|slope"
std::string formatValue(const ParamDecl& d, double value);  // "slope", "true", "2048", "0.0005"
std::string uniformName(const std::string& key);            // "bias.slope" -> "u_bias_slope"

// Values for a set of declarations. Every value is stored as double (enums as index) so that
// sweeps, JSON and uniforms treat all types alike; validation happens on every write.
class ParamSet {
 public:
  ParamSet() = default;
  explicit ParamSet(std::vector<ParamDecl> decls);

  const std::vector<ParamDecl>& decls() const { return decls_; }
  const ParamDecl* find(const std::string& key) const;
  bool has(const std::string& key) const { return find(key) != nullptr; }

  double get(const std::string& key) const;  // throws ParamError for unknown keys
  float f(const std::string& key) const { return static_cast<float>(get(key)); }
  int i(const std::string& key) const { return static_cast<int>(get(key)); }
  bool b(const std::string& key) const { return get(key) != 0.0; }
  std::string choice(const std::string& key) const;  // enum value as its name

  // Throws ParamError naming the key and what is wrong (unknown key, out of range, not a number).
  void set(const std::string& key, double value);
  void setFromString(const std::string& key, const std::string& text);
  void setAssignment(const std::string& keyEqualsValue);  // "bias.mode=slope"
  void resetToDefaults();

 private:
  std::vector<ParamDecl> decls_;
  std::map<std::string, double> values_;
};

// The GLSL define an enum's choice becomes: "bias.mode", "normal-offset" -> "SL_BIAS_MODE_IS_NORMAL_OFFSET".
std::string choiceDefineName(const std::string& key, const std::string& choice);
// "#define SL_<KEY>_IS_<CHOICE>\n" for the chosen value of every enum: shaders test `#ifdef` by
// name, never a position in the choice list (tests/param_defines_test.cpp checks every name a
// shader uses against the declarations).
std::string enumDefines(const ParamSet& params);

}  // namespace sl
