// Debug views of the PCSS blocker search, `blocker-depth` and `penumbra`
// (representations/soft/penumbra_colors.glsl): what the search pass left at this pixel.
// u_pcssBlocker is declared by the technique's pcss module (prelude, SL_AREA_LIGHT).
#include "representations/soft/penumbra_colors.glsl"
out vec4 o_color;

void main() {
#ifdef SL_AREA_LIGHT
  o_color = penumbraViewColor(pcssBlockerHere());
#else
  o_color = penumbraViewColor(vec4(0.0));  // a point light: no search ran
#endif
}
