// Debug view "disocclusion": why a pixel has no usable history.
//   grey    history used          purple  none (first frame after a cut)
//   blue    off-screen / behind the camera / beyond the far plane in the previous frame
//   orange  disoccluded (the previous frame saw another depth there)
//   yellow  rejected: moving-caster rule (pc.reject)
#define SL_DEFERRED
#include "common/visibility_term.glsl"
#include "accumulation/pixel_correct.glsl"

uniform sampler2D u_gNormal;

out vec4 o_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (texelFetch(u_gPosition, pixel, 0).w < 0.5) {
    o_color = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  vec2 raw = texelFetch(u_raw, pixel, 0).rg;
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  PcHistory h = pcHistory(pixel, texelFetch(u_gPosition, pixel, 0).xyz, N, raw.r, clamp(raw.g, 0.0, 1.0));
  vec3 color = vec3(0.35);
  if (h.state == PC_NONE) color = vec3(0.6, 0.2, 0.8);
  else if (h.state == PC_OFFSCREEN) color = vec3(0.15, 0.35, 0.95);
  else if (h.state == PC_DISOCCLUDED) color = vec3(1.0, 0.5, 0.0);
  else if (h.state == PC_REJECTED) color = vec3(0.95, 0.85, 0.1);
  o_color = vec4(color, 1.0);
}
