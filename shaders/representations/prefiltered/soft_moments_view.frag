// `blocker-depth` and `penumbra` views of the pre-filtered soft representations (vssm,
// convolution-soft): their blocker estimate (soft_moments.glsl) evaluated per G-buffer pixel, in
// pcss's colours (representations/soft/penumbra_colors.glsl), so the three can be compared.
#define SL_DEFERRED
#include "common/visibility_term.glsl"
#include "representations/soft/receiver_coord.glsl"
#include "representations/soft/penumbra_colors.glsl"
out vec4 o_color;

void main() {
  vec3 uvLayer;
  float depth = 0.0;
  vec4 b = vec4(0.0);  // not searched
  int view = 0;
#ifdef SL_AREA_LIGHT
  if (receiverShadowCoord(ivec2(gl_FragCoord.xy), uvLayer, depth)) {
    vec4 p = softMomentPenumbra(uvLayer, depth);
    view = sl_view;
    float dR = pcssLinear(depth, view), dB = pcssLinear(p.y, view);
    bool found = p.x >= kSoftMinBlockerFraction;
    b = vec4(max(dR - dB, 0.0), found ? pcssPenumbraWorld(dR, dB) : 0.0, found ? 1.0 : 0.0, p.w);
  }
#endif
  o_color = penumbraViewColor(b, view, depth);
}
