// The parameters of the PCSS penumbra model (shaders/representations/soft/penumbra.glsl), shared
// by every soft representation: pcss and the pre-filtered vssm and convolution-soft.
#pragma once

#include "core/params.h"
#include "part/colour_key.h"
#include "scene/scene_effects.h"

#include <map>
#include <string>
#include <vector>

namespace sl {
std::vector<ParamDecl> penumbraParams();
// The status line of a soft representation under an area light: "NAME: light radius R x S".
std::string softLightStatus(const std::string& name, const SceneEffects& fx, const ParamSet& params);
// The colour keys of the blocker-depth and penumbra views every soft representation draws
// (shaders/representations/soft/penumbra_colors.glsl), for each family that has one.
void addPenumbraViewKeys(std::map<std::string, ColourKey>& keys);
}  // namespace sl
