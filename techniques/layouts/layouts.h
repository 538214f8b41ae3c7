#pragma once

#include "part/part.h"

namespace sl {
void registerBasicLayouts(std::vector<std::unique_ptr<Layout>>& out);
}
