#pragma once

#include "part/part.h"

namespace sl {
void registerDepthRepresentations(std::vector<std::unique_ptr<Representation>>& out);
}
