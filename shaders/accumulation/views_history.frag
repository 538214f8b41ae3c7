// Debug view "history": s(n-1), the previous frame's history reprojected to this frame (grey);
// blue where there is none (cut, off-screen, disoccluded), yellow where a moving-caster test
// replaced it.
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
  vec3 color = vec3(0.15, 0.35, 0.95);
  if (h.state == PC_VALID) color = vec3(0.1 + 0.85 * h.s);
  else if (h.state == PC_REJECTED) color = mix(vec3(0.95, 0.85, 0.1), vec3(h.s), 0.3);
  o_color = vec4(color, 1.0);
}
