// What the colours of a debug view mean: the one description that the explorer's on-screen keys
// and headless figures draw. The renderer's common views declare theirs in
// app/render/view_keys.cpp, each family the keys of its parts' views in its family.cpp
// (Family::viewKeys); the registry's viewColourKey finds either. A view's shader and its key must
// agree: the gradients are the same stops as the GLSL (named beside each entry).
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

// The background of views drawn over the G-buffer where no geometry is.
inline const SpecialColour kBlackNoGeometry{{0.0f, 0.0f, 0.0f}, "black: no geometry (sky)"};

// A stop's label with the key's unit after it, unless the label already names it ("64+ samples"
// and "32 texels (pcss.max_radius)" stay so, "64" becomes "64 samples"): what a thumbnail's key
// prints at its end.
std::string labelWithUnit(const std::string& label, const std::string& unit);

// Colour of the gradient at t in [0, 1] (linear between stops; clamped).
glm::vec3 sampleColourKey(const ColourKey& key, float t);

}  // namespace sl
