// The colour keys of the common debug views (part/colour_key.h says what a key is); the
// aliasing key is held to the shader's mapping by tests/explorer_lecture_test.cpp.
#pragma once

#include "part/colour_key.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace sl {

// The key of a common debug view (one every technique offers) by name, or nullptr. The views of
// a part are keyed by its family (Family::viewKeys); front ends ask the registry's
// viewColourKey, which finds both.
const ColourKey* commonViewColourKey(const std::string& viewName);
// Every common view that has a key.
std::vector<std::string> commonViewsWithColourKeys();

// The aliasing view's scale: log2(pixels per texel) over [-kAliasingLog2Range, +range].
constexpr float kAliasingLog2Range = 12.0f;

}  // namespace sl
