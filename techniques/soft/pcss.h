// Soft shadows from area lights. pcss: percentage-closer soft shadows (Fernando 2005).
#pragma once

#include "part/part.h"

namespace sl {
void registerSoftRepresentations(std::vector<std::unique_ptr<Representation>>& out);
void addSoftPresets(std::vector<Preset>& out);
}  // namespace sl
