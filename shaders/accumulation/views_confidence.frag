// Debug view "confidence": grey = shadow-test confidence (eq. 5, 1 at texel centres),
// orange = the update weight w = conf^m this frame (only near-centre tests count).
#define SL_DEFERRED
#include "common/visibility_term.glsl"
#include "accumulation/pixel_correct.glsl"

uniform float u_m;
out vec4 o_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (texelFetch(u_gPosition, pixel, 0).w < 0.5) {
    o_color = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  float c = clamp(texelFetch(u_raw, pixel, 0).g, 0.0, 1.0);
  // Confidence peaks at every texel centre, so where texels are smaller than pixels a pixel's
  // sample aliases into moire. There, show what the pixel's footprint averages to instead: over
  // a texel, conf = 1 - u with u = 2 max(|dx|, |dy|) of density 2u, so the mean confidence is 1/3
  // and the mean update weight E[conf^m] = 2 / ((m + 1)(m + 2)).
  vec2 texelCoord = layoutShadowCoord(texelFetch(u_gPosition, pixel, 0).xyz).uv * u_shadowMapSize;
  float texelsPerPixel = max(fwidth(texelCoord).x, fwidth(texelCoord).y);
  // Exactly 1 (facing away: decided without the map) or 0 (outside it) is no texel pattern.
  float blend = (c >= 1.0 || c <= 0.0) ? 0.0 : smoothstep(0.5, 1.5, texelsPerPixel);
  float m = max(u_m, 1e-3);
  float w = mix(pow(c, m), 2.0 / ((m + 1.0) * (m + 2.0)), blend);
  c = mix(c, 1.0 / 3.0, blend);
  o_color = vec4(mix(vec3(c * 0.7), vec3(1.0, 0.55, 0.0), w), 1.0);
}
