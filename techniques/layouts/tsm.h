#pragma once

#include "technique.h"

namespace sl {
void registerTrapezoidalLayouts(std::vector<std::unique_ptr<Layout>>& out);
}
