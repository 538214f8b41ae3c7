#pragma once

#include "part/part.h"

namespace sl {
void registerTrapezoidalLayouts(std::vector<std::unique_ptr<Layout>>& out);
}
