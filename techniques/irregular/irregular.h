// Irregular z-buffer (Johnson et al. 2004, Aila & Laine 2004) in the GPU form of Sintorn et al.
// 2008: exact hard-shadow visibility of every visible eye sample, as a representation.
#pragma once

#include "part/part.h"

namespace sl {
void registerIrregularRepresentations(std::vector<std::unique_ptr<Representation>>& out);
void addIrregularPresets(std::vector<Preset>& out);
}  // namespace sl
