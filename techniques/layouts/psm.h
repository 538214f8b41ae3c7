#pragma once

#include "technique.h"

namespace sl {
void registerPerspectiveLayouts(std::vector<std::unique_ptr<Layout>>& out);
}
