// Debug views of the PCSS blocker search, `blocker-depth` and `penumbra`
// (representations/soft/penumbra_colors.glsl): what the search pass left at this pixel, in texels
// of the view the pixel's test reads (its own cascade).
// u_pcssBlocker is declared by the technique's pcss module (prelude, SL_AREA_LIGHT).
#define SL_DEFERRED
#include "common/visibility_term.glsl"
#include "representations/soft/receiver_coord.glsl"
#include "representations/soft/penumbra_colors.glsl"
out vec4 o_color;

void main() {
#ifdef SL_AREA_LIGHT
  vec3 uvLayer;
  float depth;
  vec4 b = pcssBlockerHere();
  if (!receiverShadowCoord(ivec2(gl_FragCoord.xy), uvLayer, depth)) b = vec4(0.0);  // not searched there
  o_color = penumbraViewColor(b, sl_view, depth);
#else
  o_color = penumbraViewColor(vec4(0.0), 0, 0.0);  // a point light: no search ran
#endif
}
