// Pixel-correct shadow maps (Scherzer, Jeschke, Wimmer, EGSR 2007) in one pass, as the paper
// does with multiple render targets: shadow test f(n) with its confidence (eq. 5), history
// lookup by reprojection (eq. 4), confidence-weighted update and shading.
//   w    = conf^m                        (eq. 6)
//   s(n) = a f(n) + (1 - a) s(n-1)       (eq. 2/3), s(n) = f(n) where there is no history
//   a    = w (the paper), or with pc.warmup a = w / max(W + w, 1), W = accumulated weight
//          (min(sum of w, 1)): a confidence-weighted mean until the pixel has gathered a total
//          weight of 1, exactly the paper's update from then on.
// Needs the technique prelude (layout + representation modules).
#include "common/visibility_term.glsl"
#include "common/shading.glsl"
#include "accumulation/pixel_correct.glsl"

uniform sampler2D u_gNormal;
uniform float u_pc_warmup;
uniform float u_m;
in vec2 v_uv;

layout(location = 0) out vec4 o_color;
layout(location = 1) out vec2 o_visibility;  // r: s(n) shown, g: update weight a (1 = no history)
layout(location = 2) out vec4 o_history;     // r: s(n), g: linear view depth (0 = none), b: W
layout(location = 3) out vec2 o_raw;         // this frame's test and confidence, for the views

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) {
    o_color = vec4(skyColor(v_uv.y), 1.0);
    o_visibility = vec2(1.0, 1.0);
    o_history = vec4(0.0);
    o_raw = vec2(1.0, 0.0);
    return;
  }
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  vec2 raw = visibilityTerm(P.xyz, N);
  float f = raw.x;
  float c = pcFinite(raw.y) ? clamp(raw.y, 0.0, 1.0) : 0.0;
  PcHistory h = pcHistory(pixel, P.xyz, N, f, c);
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
  o_raw = raw;
  o_visibility = vec2(s, a);
  o_history = vec4(s, pcFinite(depth) && depth > 0.0 ? depth : 0.0, W, 0.0);
  o_color = shadePixel(pixel, P.xyz, N, s);
}
