#pragma once

#include "part/part.h"

namespace sl {
void registerFacePartitionedLayouts(std::vector<std::unique_ptr<Layout>>& out);
}
