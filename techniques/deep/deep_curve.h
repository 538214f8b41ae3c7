// The transmittance function of one deep texel against light depth, as the deep map stores it
// and as the reference traces it along the same light ray (the explorer's V plot; tests).
#pragma once

#include "deep/deep_state.h"
#include "reference/reference.h"

#include <vector>

namespace sl {

// T at `samples` depths evenly over [0,1] at the deep texel holding uv in view `layer`, from the
// stored nodes (read back from the GPU; piecewise linear as representations/deep.glsl, without
// the 2x2 filter). Empty when the state has no deep map.
std::vector<float> deepTexelCurve(const DeepState& state, glm::vec2 uv, int layer, int samples);
// The reference's light fraction at the same depths on the ray through that texel's centre.
std::vector<float> referenceTexelCurve(const ReferenceTracer& tracer, const LightView& view, const DeepState& state,
                                       glm::vec2 uv, int samples);
// World point at stored depth d on the light ray through map position uv of `view`.
glm::vec3 lightRayPoint(const LightView& view, glm::vec2 uv, float d);

}  // namespace sl
