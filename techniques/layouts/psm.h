#pragma once

#include "part/part.h"

namespace sl {
void registerPerspectiveLayouts(std::vector<std::unique_ptr<Layout>>& out);
}
