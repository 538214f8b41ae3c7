// The reconstruction family's manifest: its parts and presets (registry.cpp lists the families).
#include "reconstruction/reconstruction.h"
#include "part/family.h"

namespace sl {

namespace {

// The silhouette map's points and the forward splats against the backward test.
void addReconstructionViewKeys(std::map<std::string, ColourKey>& keys) {
  // shaders/views/silhouette_points.frag
  keys["silhouette-points"] = {"silhouette points over the depth map (layer 0)",
                               "",
                               {{0.0f, {0.55f, 0.55f, 0.55f}, "depth 0 (near)"},
                                {0.25f, {0.375f, 0.375f, 0.375f}, "depth 0.25"},
                                {0.5f, {0.227f, 0.227f, 0.227f}, "depth 0.5"},
                                {0.75f, {0.1125f, 0.1125f, 0.1125f}, "depth 0.75"},
                                {1.0f, {0.05f, 0.05f, 0.05f}, "depth near 1 (far)"}},
                               {{{1.0f, 0.55f, 0.1f}, "orange (70% over the grey): texel holds a point"},
                                {{1.0f, 0.1f, 0.1f}, "red: the point itself (dot of >= 1.5 px)"},
                                {{0.0f, 0.0f, 0.0f}, "black: empty (depth 1, nothing drawn)"},
                                {{0.08f, 0.08f, 0.10f}, "near-black: outside the map (letterbox)"}},
                               "grey = 0.5 (1 - depth)^1.5 + 0.05; under ~3 px per texel red hides orange"};
  // shaders/accumulation/views_forward_holes.frag
  keys["forward-holes"] = {"forward splats against the backward nearest test",
                           "",
                           {},
                           {{{0.9f, 0.9f, 0.9f}, "white: lit by a splat and by the backward test"},
                            {{0.1f, 0.9f, 0.9f}, "cyan: splat lit, backward test shadows (leak)"},
                            {{1.0f, 0.1f, 0.9f}, "magenta: hole (backward lit, no splat reached)"},
                            {{0.2f, 0.2f, 0.2f}, "dark grey: shadow in both"},
                            {{0.1f, 0.1f, 0.15f}, "near-black: no geometry (sky)"}},
                           "magenta here is a hole, not NaN; each side counts as lit above 0.5"};
}

}  // namespace

Family reconstructionFamily() {
  Family f{.id = "reconstruction",
           .summary =
               "reconstruction beyond one depth per texel: silhouette maps (Sen et al. 2003) and forward shadow "
               "mapping (Zhang 1998)"};
  registerReconstructionRepresentations(f.representations);
  registerForwardAccumulation(f.accumulations);
  addReconstructionPresets(f.presets);
  addReconstructionViewKeys(f.viewKeys);
  return f;
}

}  // namespace sl
