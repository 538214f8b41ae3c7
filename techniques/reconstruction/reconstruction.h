#pragma once

#include "part/part.h"

namespace sl {
// Representations that reconstruct the shadow edge beyond one depth per texel (silhouette maps).
void registerReconstructionRepresentations(std::vector<std::unique_ptr<Representation>>& out);
// Forward shadow mapping (Zhang 1998): light-view samples splatted into the eye view.
void registerForwardAccumulation(std::vector<std::unique_ptr<Accumulation>>& out);
// Presets of this family.
void addReconstructionPresets(std::vector<Preset>& out);
}  // namespace sl
