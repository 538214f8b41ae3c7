// Screen-space shadow term for accumulations and debug views: (visibility, confidence).
#include "common/visibility_term.glsl"

uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
out vec2 o_visibility;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  o_visibility = P.w < 0.5 ? vec2(1.0, 0.0) : visibilityTerm(P.xyz, normalize(texelFetch(u_gNormal, pixel, 0).xyz));
}
