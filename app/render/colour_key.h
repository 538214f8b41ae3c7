// What the colours of a debug view mean, in one place, so every place that shows a view (the
// explorer's thumbnails, headless figures) can draw the same key beside it. Must follow the
// shaders in shaders/views/ (and the accumulations' views): a shader's ramp changes here too.
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace sl {

struct ColourKeyStop {
  float at = 0.0f;  // 0..1 along the key
  glm::vec3 colour{0.0f};
};

struct ColourKey {
  std::string title;                                  // what is measured, e.g. "screen pixels per shadow-map texel"
  std::vector<ColourKeyStop> stops;                   // piecewise-linear ramp; empty: the view has no key
  std::vector<std::pair<float, std::string>> labels;  // tick labels at positions 0..1
  bool valid() const { return !stops.empty(); }
  glm::vec3 sample(float t) const;  // the ramp at t (clamped)
};

// The key of a view by name; an empty key (valid() false) for views whose colours are not a
// scale (the shaded scene, the texel checkerboard, the light-space overview).
ColourKey viewColourKey(const std::string& viewName);

}  // namespace sl
