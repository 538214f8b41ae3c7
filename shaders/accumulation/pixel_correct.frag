// Pixel-correct shadow maps (Scherzer, Jeschke, Wimmer, EGSR 2007): history buffer update.
//   w    = conf^m                        (eq. 6, conf from eq. 5 in passes/visibility.frag)
//   s(n) = a f(n) + (1 - a) s(n-1)       (eq. 2/3), s(n) = f(n) where there is no history
//   a    = w (the paper), or with pc.warmup a = w / max(W + w, 1), W = accumulated weight
//          (min(sum of w, 1)): a confidence-weighted mean until the pixel has gathered a total
//          weight of 1, exactly the paper's update from then on.
uniform float u_pc_warmup;
#include "accumulation/pixel_correct.glsl"

uniform float u_m;

layout(location = 0) out vec2 o_visibility;  // r: s(n) shown, g: update weight a (1 = no history)
layout(location = 1) out vec4 o_history;     // r: s(n), g: linear view depth (0 = none), b: W

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  vec2 raw = texelFetch(u_raw, pixel, 0).rg;
  if (P.w < 0.5) {
    o_visibility = vec2(raw.r, 1.0);
    o_history = vec4(0.0);
    return;
  }
  float f = raw.r;
  float c = pcFinite(raw.g) ? clamp(raw.g, 0.0, 1.0) : 0.0;
  PcHistory h = pcHistory(pixel, f, c);
  float w = pow(c, max(u_m, 1e-3));
  float s = f;
  float a = 1.0, W = w;
  if (h.state == PC_VALID) {
    a = u_pc_warmup > 0.5 ? w / max(h.W + w, 1.0) : w;
    s = clamp(a * f + (1.0 - a) * h.s, 0.0, 1.0);
    W = min(h.W + w, 1.0);
  }
  if (!pcFinite(s)) s = h.state == PC_VALID ? h.s : 1.0;
  float depth = pcLinearDepth(P.xyz);
  o_visibility = vec2(s, a);
  o_history = vec4(s, pcFinite(depth) && depth > 0.0 ? depth : 0.0, W, 0.0);
}
