#include "param_hints.h"

#include "technique.h"

#include <algorithm>
#include <vector>

namespace sl {

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

namespace {

// The presets whose composition declares `key` (each preset built once; only on this error path).
std::vector<std::string> presetsDeclaring(const std::string& key) {
  std::vector<std::string> ids;
  for (const Preset& p : allPresets())
    if (makeTechnique(p.id).params.has(key)) ids.push_back(p.id);
  return ids;
}

// The declared key nearest to `key`, "" when none is within a quarter of its length (at least 2).
std::string nearestKey(const ParamSet& params, const std::string& key) {
  std::string best;
  size_t bestDistance = std::max<size_t>(2, key.size() / 4) + 1;
  for (const ParamDecl& d : params.decls())
    if (const size_t dist = editDistance(key, d.key); dist < bestDistance) {
      bestDistance = dist;
      best = d.key;
    }
  return best;
}

}  // namespace

std::string unknownParameterMessage(const std::string& presetId, const ParamSet& params, const std::string& key) {
  std::string msg = "unknown parameter '" + key + "' for preset '" + presetId + "'";
  if (const std::vector<std::string> ids = presetsDeclaring(key); !ids.empty()) {
    std::string list;
    for (size_t i = 0; i < ids.size() && i < 8; ++i) list += (i ? ", " : "") + ids[i];
    if (ids.size() > 8) list += ", ... (" + std::to_string(ids.size()) + " in all)";
    return msg + " (declared by the presets " + list + ": choose one with --technique)";
  }
  if (const std::string near = nearestKey(params, key); !near.empty()) return msg + " (did you mean '" + near + "'?)";
  return msg + " (see `shadowlab list`)";
}

}  // namespace sl
