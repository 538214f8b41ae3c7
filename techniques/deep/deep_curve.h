// The transmittance function of one deep texel against light depth, as the deep map stores it
// (DeepState::visibilityCurve: the explorer's V plot; tests).
#pragma once

#include "deep/deep_state.h"

#include <vector>

namespace sl {

// T at `samples` depths evenly over [0,1] at the deep texel holding uv in view `layer`, from the
// stored nodes (read back from the GPU; piecewise linear as representations/deep.glsl, without
// the 2x2 filter). Empty when the state has no deep map.
std::vector<float> deepTexelCurve(const DeepState& state, glm::vec2 uv, int layer, int samples);
}  // namespace sl
