// Colour keys of the debug views (see colour_key.h); the ramps copy the views' shaders.
#include "render/colour_key.h"

#include <algorithm>
#include <cmath>

namespace sl {

glm::vec3 ColourKey::sample(float t) const {
  if (stops.empty()) return glm::vec3(0.0f);
  t = std::clamp(t, 0.0f, 1.0f);
  for (size_t i = 1; i < stops.size(); ++i)
    if (t <= stops[i].at) {
      const float span = std::max(stops[i].at - stops[i - 1].at, 1e-6f);
      return glm::mix(stops[i - 1].colour, stops[i].colour, (t - stops[i - 1].at) / span);
    }
  return stops.back().colour;
}

ColourKey viewColourKey(const std::string& viewName) {
  ColourKey k;
  if (viewName == "aliasing") {
    // shaders/views/aliasing.frag: log4 of pixels per texel, blue (-1) .. green (0) .. red (+1).
    k.title = "screen pixels per shadow-map texel";
    k.stops = {{0.0f, {0.1f, 0.3f, 1.0f}}, {0.5f, {0.1f, 0.8f, 0.2f}}, {1.0f, {1.0f, 0.1f, 0.05f}}};
    k.labels = {{0.0f, "1/16 (over)"}, {0.5f, "1"}, {1.0f, "16 (under)"}};
  } else if (viewName == "visibility") {
    k.title = "visibility";  // shaders/views/visibility.frag: grey level, magenta = NaN
    k.stops = {{0.0f, glm::vec3(0.0f)}, {1.0f, glm::vec3(1.0f)}};
    k.labels = {{0.0f, "0 shadow"}, {1.0f, "1 lit"}};
  } else if (viewName == "shadowmap") {
    k.title = "stored light depth";  // shaders/views/shadowmap.frag: pow(1 - d, 1.5) * 0.9 + 0.1
    for (int i = 0; i <= 4; ++i) {
      const float d = i / 4.0f;
      k.stops.push_back({d, glm::vec3(std::pow(1.0f - d, 1.5f) * 0.9f + 0.1f)});
    }
    k.labels = {{0.0f, "near"}, {1.0f, "far"}};
  }
  return k;
}

}  // namespace sl
