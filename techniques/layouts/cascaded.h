#pragma once

#include "part/part.h"

namespace sl {
void registerCascadedLayouts(std::vector<std::unique_ptr<Layout>>& out);

// The `cascades` debug view (techniques/layouts/cascades_view.cpp): the split each pixel reads,
// coloured, blend bands hatched. Adds its pass when ctx.viewTargets asks for it.
void addCascadesViewPass(FrameGraph& graph, const PartContext& ctx);
}  // namespace sl
