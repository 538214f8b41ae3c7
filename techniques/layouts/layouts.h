#pragma once

#include "technique.h"

namespace sl {
void registerBasicLayouts(std::vector<std::unique_ptr<Layout>>& out);
}
