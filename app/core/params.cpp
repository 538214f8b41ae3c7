#include "core/params.h"

#include <cctype>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace sl {

const char* paramTypeName(ParamType t) {
  switch (t) {
    case ParamType::Float:
      return "float";
    case ParamType::Int:
      return "int";
    case ParamType::Bool:
      return "bool";
    case ParamType::Enum:
      return "enum";
  }
  return "?";
}

static std::string shortNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string describeRange(const ParamDecl& d) {
  switch (d.type) {
    case ParamType::Bool:
      return "on|off";
    case ParamType::Enum: {
      std::string r;
      for (size_t i = 0; i < d.choices.size(); ++i) r += (i ? "|" : "") + d.choices[i];
      return r;
    }
    default:
      return shortNumber(d.min) + ".." + shortNumber(d.max);
  }
}

std::string formatValue(const ParamDecl& d, double value) {
  switch (d.type) {
    case ParamType::Bool:
      return value != 0.0 ? "on" : "off";
    case ParamType::Enum: {
      size_t idx = static_cast<size_t>(value);
      return idx < d.choices.size() ? d.choices[idx] : "?";
    }
    case ParamType::Int:
      return std::to_string(static_cast<long long>(value));
    default:
      return shortNumber(value);
  }
}

std::string uniformName(const std::string& key) {
  std::string n = "u_";
  for (char c : key) n += (c == '.' || c == '-') ? '_' : c;
  return n;
}

std::string choiceDefineName(const std::string& key, const std::string& choice) {
  std::string n = "SL_";
  for (const std::string& part : {key, std::string("."), choice})
    for (char c : part)
      n += std::isalnum(static_cast<unsigned char>(c)) ? char(std::toupper(static_cast<unsigned char>(c))) : '_';
  return n;
}

std::string enumDefines(const ParamSet& params) {
  std::string out;
  for (const ParamDecl& d : params.decls())
    if (d.type == ParamType::Enum) out += "#define " + choiceDefineName(d.key, "is." + params.choice(d.key)) + "\n";
  return out;
}

ParamSet::ParamSet(std::vector<ParamDecl> decls) : decls_(std::move(decls)) { resetToDefaults(); }

const ParamDecl* ParamSet::find(const std::string& key) const {
  for (const auto& d : decls_)
    if (d.key == key) return &d;
  return nullptr;
}

double ParamSet::get(const std::string& key) const {
  auto it = values_.find(key);
  if (it == values_.end()) throw ParamError("unknown parameter '" + key + "'");
  return it->second;
}

std::string ParamSet::choice(const std::string& key) const {
  const ParamDecl* d = find(key);
  if (!d) throw ParamError("unknown parameter '" + key + "'");
  return formatValue(*d, get(key));
}

void ParamSet::set(const std::string& key, double value) {
  const ParamDecl* d = find(key);
  if (!d) throw ParamError("unknown parameter '" + key + "' (see `shadowlab list`)");
  if (!std::isfinite(value)) throw ParamError(key + ": value must be finite");
  switch (d->type) {
    case ParamType::Bool:
      value = value != 0.0 ? 1.0 : 0.0;
      break;
    case ParamType::Enum:
      if (value < 0 || value >= static_cast<double>(d->choices.size()) || value != std::floor(value))
        throw ParamError(key + ": choice index out of range (" + describeRange(*d) + ")");
      break;
    case ParamType::Int:
      if (value != std::floor(value)) throw ParamError(key + ": expected an integer");
      [[fallthrough]];
    case ParamType::Float:
      if (value < d->min || value > d->max)
        throw ParamError(key + ": " + shortNumber(value) + " is outside " + describeRange(*d) +
                         (d->unit.empty() ? "" : " " + d->unit));
      break;
  }
  values_[key] = value;
}

void ParamSet::setFromString(const std::string& key, const std::string& text) {
  const ParamDecl* d = find(key);
  if (!d) throw ParamError("unknown parameter '" + key + "' (see `shadowlab list`)");
  if (d->type == ParamType::Enum) {
    for (size_t i = 0; i < d->choices.size(); ++i)
      if (d->choices[i] == text) return set(key, static_cast<double>(i));
    throw ParamError(key + ": '" + text + "' is not one of " + describeRange(*d));
  }
  if (d->type == ParamType::Bool) {
    if (text == "on" || text == "true" || text == "1") return set(key, 1);
    if (text == "off" || text == "false" || text == "0") return set(key, 0);
    throw ParamError(key + ": '" + text + "' is not on|off");
  }
  char* end = nullptr;
  double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || *end != '\0') throw ParamError(key + ": '" + text + "' is not a number");
  set(key, v);
}

void ParamSet::setAssignment(const std::string& kv) {
  auto eq = kv.find('=');
  if (eq == std::string::npos || eq == 0) throw ParamError("expected key=value, got '" + kv + "'");
  setFromString(kv.substr(0, eq), kv.substr(eq + 1));
}

void ParamSet::resetToDefaults() {
  values_.clear();
  for (const auto& d : decls_) values_[d.key] = d.defaultValue;
}

}  // namespace sl
