// The parameters of the PCSS penumbra model (shaders/representations/soft/penumbra.glsl), shared
// by every soft representation: pcss and the pre-filtered vssm and convolution-soft.
#pragma once

#include "core/params.h"

#include <vector>

namespace sl {
std::vector<ParamDecl> penumbraParams();
}  // namespace sl
