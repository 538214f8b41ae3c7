#include "part/colour_key.h"

#include <algorithm>

namespace sl {

std::string labelWithUnit(const std::string& label, const std::string& unit) {
  if (unit.empty() || label.find(unit) != std::string::npos) return label;
  return label + " " + unit;
}

glm::vec3 sampleColourKey(const ColourKey& key, float t) {
  if (key.stops.empty()) return glm::vec3(0.0f);
  t = std::clamp(t, 0.0f, 1.0f);
  if (t <= key.stops.front().position) return key.stops.front().colour;
  for (size_t i = 1; i < key.stops.size(); ++i) {
    const ColourStop& a = key.stops[i - 1];
    const ColourStop& b = key.stops[i];
    if (t <= b.position) {
      const float span = std::max(b.position - a.position, 1e-6f);
      return glm::mix(a.colour, b.colour, (t - a.position) / span);
    }
  }
  return key.stops.back().colour;
}

}  // namespace sl
