// Uniforms every technique program reads: each parameter as u_<key>, the map size, the light.
#pragma once

#include "part/part.h"

#include <string>

namespace sl {

class Program;

// Uploads every technique parameter as float uniform u_<key>, the shadow-map size and the light.
// (The light views themselves are a uniform block: the renderer's LightViewsBuffer.)
void setTechniqueUniforms(const Program& p, const Technique& t, const LightSpace& ls, const Light& light);
// The same with the values a frame uses (the renderer's: the map size a texel budget gave).
void setTechniqueUniforms(const Program& p, const ParamSet& params, const LightSpace& ls, const Light& light);
// The light's uniforms alone (common/light.glsl), for passes that shade without a technique.
void setLightUniforms(const Program& p, const Light& light);
// The light's compile-time specialisation of common/light.glsl: SL_SPOT_LIGHT for every light
// with a position (spot and point), SL_POINT_LIGHT for a point light (no cone, a range).
std::string lightDefines(const Light& light);

}  // namespace sl
