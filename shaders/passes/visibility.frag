// Screen-space shadow term for accumulations and debug views: (visibility, confidence).
#define SL_DEFERRED
#include "common/visibility_term.glsl"

uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
out vec2 o_visibility;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) {
    o_visibility = vec2(1.0, 0.0);
    return;
  }
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  o_visibility = visibilityTerm(P.xyz, N, gbufferFacetNormal(pixel, N));
}
