// The parameters of the PCSS penumbra model (shaders/representations/soft/penumbra.glsl), shared
// by every soft representation: pcss and the pre-filtered vssm and convolution-soft.
#pragma once

#include "core/params.h"
#include "scene/scene_effects.h"

#include <string>
#include <vector>

namespace sl {
std::vector<ParamDecl> penumbraParams();
// The status line of a soft representation under an area light: "NAME: light radius R x S".
std::string softLightStatus(const std::string& name, const SceneEffects& fx, const ParamSet& params);
}  // namespace sl
