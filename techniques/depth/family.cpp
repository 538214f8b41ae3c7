// The depth family's manifest: its parts and presets (registry.cpp lists the families).
#include "depth/depth_representations.h"
#include "part/family.h"

namespace sl {

namespace {

// The depth test over the focused (or whole-scene) map, with its filters.
void addDepthTestPresets(std::vector<Preset>& v) {
  v.insert(
      v.end(),
      {
          {"standard", "focused shadow map, nearest depth test", "focused", "depth-nearest", "none", {}},
          {"uniform",
           "one shadow map over the whole scene, nearest depth test",
           "uniform",
           "depth-nearest",
           "none",
           {}},
          {"pcf", "focused shadow map, 3x3 box PCF", "focused", "depth-pcf", "none", {"pcf.kernel=3"}},
          {"poisson", "focused shadow map, rotated Poisson-disk PCF", "focused", "depth-poisson", "none", {}},
          {"bilinear", "focused shadow map, hardware bilinear depth compare", "focused", "depth-bilinear", "none", {}},
      });
}

}  // namespace

Family depthFamily() {
  Family f{.id = "depth",
           .summary =
               "one depth per texel, visibility reconstructed by a nearest, box, Poisson or bilinear depth test "
               "(Williams 1978, Reeves et al. 1987)"};
  registerDepthRepresentations(f.representations);
  addDepthTestPresets(f.presets);
  return f;
}

}  // namespace sl
