// Declared once for every soft representation (pcss, vssm, convolution-soft): the light size the
// penumbra model uses and the largest region it may search and filter.
#include "part/penumbra_params.h"

#include <cstdio>

namespace sl {

std::vector<ParamDecl> penumbraParams() {
  return {
      {.key = "pcss.light_scale",
       .type = ParamType::Float,
       .min = 0,
       .max = 8,
       .defaultValue = 1,
       .unit = "x light.radius",
       .help = "light size used for search region and penumbra, as a multiple of the scene's light.radius"},
      {.key = "pcss.max_radius",
       .type = ParamType::Float,
       .min = 1,
       .max = 128,
       .defaultValue = 32,
       .unit = "texels",
       .help = "largest search region and filter radius (bounds the cost where a light is huge)"},
  };
}

std::string softLightStatus(const std::string& name, const SceneEffects& fx, const ParamSet& params) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%s: light radius %g x %g", name.c_str(), fx.lightRadius,
                params.get("pcss.light_scale"));
  return buf;
}

}  // namespace sl
