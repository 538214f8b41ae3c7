#pragma once

#include "technique.h"

namespace sl {
void registerWarpedLayouts(std::vector<std::unique_ptr<Layout>>& out);
}
