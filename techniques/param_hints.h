// Helpful messages for a parameter a technique does not declare: the presets that do declare it
// (`--technique standard --set pcf.kernel=5`), or the nearest declared key for a typo.
#pragma once

#include "core/params.h"

#include <string>

namespace sl {

// "unknown parameter 'pcf.kernel' for preset 'standard' (declared by the presets pcf, pcss, ...:
// choose one with --technique)", or "... (did you mean 'shadowmap.size'?)", or, with no near key,
// "... (see `shadowlab list`)".
std::string unknownParameterMessage(const std::string& presetId, const ParamSet& params, const std::string& key);

// Levenshtein distance (insertions, deletions, substitutions), for the typo suggestion.
size_t editDistance(const std::string& a, const std::string& b);

}  // namespace sl
