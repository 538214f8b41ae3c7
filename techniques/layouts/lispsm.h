#pragma once

#include "technique.h"

#include <vector>

namespace sl {
void registerWarpedLayouts(std::vector<std::unique_ptr<Layout>>& out);

// The LiSPSM view of `receivers` (with `casters` along their light rays) for a camera with view
// matrix `cameraView`, n = nScale x n_opt; a spot light, or a view (anti)parallel to the light,
// gets the focused map instead. Cascades call it once per split (z-partitioning and warping).
LightView lispsmView(const Light& light, const glm::mat4& cameraView, const std::vector<glm::vec3>& receivers,
                     const std::vector<glm::vec3>& casters, float nScale, int size, const LayoutJitter& jitter);
}  // namespace sl
