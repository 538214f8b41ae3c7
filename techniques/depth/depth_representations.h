#pragma once

#include "technique.h"

namespace sl {
void registerDepthRepresentations(std::vector<std::unique_ptr<Representation>>& out);
}
