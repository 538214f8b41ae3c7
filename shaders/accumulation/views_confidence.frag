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
  float w = pow(c, max(u_m, 1e-3));
  o_color = vec4(mix(vec3(c * 0.7), vec3(1.0, 0.55, 0.0), w), 1.0);
}
