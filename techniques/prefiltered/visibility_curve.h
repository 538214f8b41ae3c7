// Visibility as a function of receiver depth at one texel of a pre-filtered map, evaluated by
// the representation's own GLSL (shaders/views/visibility_curve.frag), and the true curve of
// the same texel: the fraction of the filter box's stored depths at or behind each depth.
#pragma once

#include "gl/shader_library.h"
#include "prefiltered/moment_state.h"

#include <glm/glm.hpp>

#include <vector>

namespace sl {

// `samples` receiver depths evenly over [0, 1]; the state must hold a filtered frame of `t`.
std::vector<float> reconstructedCurve(ShaderLibrary& shaders, const Technique& t, const MomentMapState& state,
                                      const glm::vec3& uvLayer, int samples);
// The lit fraction of the width x width box of depth texels around uv in `layer`, per depth
// (reads back only that box).
std::vector<float> trueCurve(const Texture2D& depth, const glm::vec3& uvLayer, int width, int samples);
}  // namespace sl
