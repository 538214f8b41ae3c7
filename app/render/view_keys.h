// What the colours of each debug view mean: the one description that the explorer's on-screen
// keys and headless figures draw. A view's shader and its key must agree; the gradients here
// are the same stops as the GLSL (named beside each entry), and tests/view_keys_test.cpp holds
// the aliasing one to the shader's mapping.
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace sl {

struct ColourStop {
  float position = 0;  // 0..1 along the bar
  glm::vec3 colour{0.0f};
  std::string label;  // value printed at this stop ("" = none)
};

// A colour with a fixed meaning outside (or instead of) the gradient: background, NaN, states.
struct SpecialColour {
  glm::vec3 colour{0.0f};
  std::string meaning;
};

struct ColourKey {
  std::string title;              // what the gradient measures
  std::string unit;               // of the gradient's labels ("" = none)
  std::vector<ColourStop> stops;  // empty: the view is categorical (specials only)
  std::vector<SpecialColour> specials;
  std::string note;  // one line on how to read it ("" = none)
};

// The key of a debug view by name, or nullptr for views whose colours are the scene itself.
const ColourKey* viewColourKey(const std::string& viewName);
// Every view that has a key (for tests and `shadowlab list`).
std::vector<std::string> viewsWithColourKeys();
// Colour of the gradient at t in [0, 1] (linear between stops; clamped).
glm::vec3 sampleColourKey(const ColourKey& key, float t);

// The aliasing view's scale: log2(pixels per texel) over [-kAliasingLog2Range, +range].
constexpr float kAliasingLog2Range = 12.0f;

}  // namespace sl
