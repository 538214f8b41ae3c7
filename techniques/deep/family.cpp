// The deep family's manifest: its parts and presets (registry.cpp lists the families).
#include "deep/deep_representation.h"
#include "part/family.h"

namespace sl {

namespace {

// The deep shadow map's view: how many nodes each texel's transmittance function kept.
void addDeepViewKeys(std::map<std::string, ColourKey>& keys) {
  // shaders/views/deep_nodes.frag (deepRamp, countColor); plain grey clear in techniques/deep/deep_state.cpp
  keys["deep-nodes"] = {"nodes used per texel of the deep shadow map (layer 0)",
                        "nodes",
                        {{0.0f, {0.15f, 0.10f, 0.40f}, "1 node"},
                         {0.333f, {0.10f, 0.50f, 0.55f}, "3.3 nodes"},
                         {0.667f, {0.35f, 0.75f, 0.35f}, "5.7 nodes"},
                         {1.0f, {0.98f, 0.90f, 0.20f}, "8 nodes (deep.nodes)"}},
                        {{{0.0f, 0.0f, 0.0f}, "black: 0 nodes (empty function)"},
                         {{0.5f, 0.5f, 0.5f}, "grey: notch between bands of the bottom key"},
                         {{0.2f, 0.2f, 0.2f}, "dark grey (whole view): no semi-transparent casters"}},
                        "ramp 1..deep.nodes (labels for 8); bottom band: a band per count from 0"};
}

}  // namespace

Family deepFamily() {
  Family f{.id = "deep",
           .summary = "deep shadow maps: transmittance per light texel for hair and smoke (Lokovic & Veach 2000)"};
  registerDeepRepresentations(f.representations);
  addDeepPresets(f.presets);
  addDeepViewKeys(f.viewKeys);
  return f;
}

}  // namespace sl
