#pragma once

#include "part/part.h"

namespace sl {
// vsm, esm, evsm, gaussian, ewgf, msm, convolution (techniques/prefiltered/README.md).
void registerPrefilteredRepresentations(std::vector<std::unique_ptr<Representation>>& out);
// Their presets: focused layout, no accumulation.
void addPrefilteredPresets(std::vector<Preset>& out);
}  // namespace sl
