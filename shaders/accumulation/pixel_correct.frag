// Pixel-correct shadow maps (Scherzer, Jeschke, Wimmer, EGSR 2007): history buffer update.
//   w    = conf^m                        (eq. 6, conf from eq. 5 in passes/visibility.frag)
//   s(n) = w f(n) + (1 - w) s(n-1)       (eq. 2/3), s(n) = f(n) where there is no history
#include "accumulation/pixel_correct.glsl"

uniform float u_m;

layout(location = 0) out vec2 o_visibility;  // r: s(n) shown, g: weight w used (1 = no history)
layout(location = 1) out vec2 o_history;     // r: s(n), g: linear view depth (0 = none)

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  vec2 raw = texelFetch(u_raw, pixel, 0).rg;
  if (P.w < 0.5) {
    o_visibility = vec2(raw.r, 1.0);
    o_history = vec2(0.0);
    return;
  }
  float f = raw.r;
  float c = pcFinite(raw.g) ? clamp(raw.g, 0.0, 1.0) : 0.0;
  PcHistory h = pcHistory(pixel, f, c);
  float w = pow(c, max(u_m, 1e-3));
  float s = f;
  if (h.state == PC_VALID) s = clamp(w * f + (1.0 - w) * h.s, 0.0, 1.0);
  else w = 1.0;
  if (!pcFinite(s)) s = h.state == PC_VALID ? h.s : 1.0;
  float depth = pcLinearDepth(P.xyz);
  o_visibility = vec2(s, w);
  o_history = vec2(s, pcFinite(depth) && depth > 0.0 ? depth : 0.0);
}
