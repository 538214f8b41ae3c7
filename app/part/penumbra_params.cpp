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

void addPenumbraViewKeys(std::map<std::string, ColourKey>& keys) {
  // shaders/representations/soft/penumbra_colors.glsl (penumbraViewColor, softRamp), drawn by
  // shaders/representations/soft/pcss_view.frag and shaders/representations/prefiltered/soft_moments_view.frag
  keys["blocker-depth"] = {"receiver-to-blocker distance (log scale)",
                           "% of depth range",
                           {{0.0f, {0.0f, 0.0f, 0.5f}, "0% (contact)"},
                            {0.125f, {0.0f, 0.0f, 1.0f}, "1.1%"},
                            {0.375f, {0.0f, 1.0f, 1.0f}, "5.9%"},
                            {0.625f, {1.0f, 1.0f, 0.0f}, "20%"},
                            {0.875f, {1.0f, 0.0f, 0.0f}, "59%"},
                            {1.0f, {0.5f, 0.0f, 0.0f}, "100%"}},
                           {{{0.0f, 0.0f, 0.0f}, "black: no blocker found (lit)"},
                            {{0.25f, 0.25f, 0.25f}, "grey: not searched (sky, facing away, off map, point light)"}},
                           "log(1 + 64 d/range) / log 65; range: far - near of the pixel's light view"};
  // shaders/representations/soft/penumbra_colors.glsl (penumbraViewColor with SL_VIEW_PENUMBRA), drawn by
  // shaders/representations/soft/pcss_view.frag and shaders/representations/prefiltered/soft_moments_view.frag
  keys["penumbra"] = {"penumbra filter radius (log, texels of its view)",
                      "texels",
                      {{0.0f, {0.0f, 0.0f, 0.5f}, "1 texel"},
                       {0.125f, {0.0f, 0.0f, 1.0f}, "1.5 texels"},
                       {0.375f, {0.0f, 1.0f, 1.0f}, "3.7 texels"},
                       {0.625f, {1.0f, 1.0f, 0.0f}, "8.7 texels"},
                       {0.875f, {1.0f, 0.0f, 0.0f}, "21 texels"},
                       {1.0f, {0.5f, 0.0f, 0.0f}, "32 texels (pcss.max_radius)"}},
                      {{{0.0f, 0.0f, 0.0f}, "black: no blocker found (lit)"},
                       {{0.25f, 0.25f, 0.25f}, "grey: not searched (sky, facing away, off map, point light)"}},
                      "log2 scale from 1 texel to pcss.max_radius (labels for the default 32)"};
}

}  // namespace sl
