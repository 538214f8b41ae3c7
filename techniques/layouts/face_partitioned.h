#pragma once

#include "technique.h"

namespace sl {
void registerFacePartitionedLayouts(std::vector<std::unique_ptr<Layout>>& out);
}
