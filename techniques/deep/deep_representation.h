// Deep shadow maps (Lokovic & Veach 2000): transmittance functions per light texel for hair and
// smoke, plus the depth test for opaque casters. techniques/deep/README.md.
#pragma once

#include "part/part.h"

#include <memory>
#include <vector>

namespace sl {

void registerDeepRepresentations(std::vector<std::unique_ptr<Representation>>& out);
void addDeepPresets(std::vector<Preset>& presets);

}  // namespace sl
