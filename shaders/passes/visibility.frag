// The shadow term of every covered pixel: layout projection + representation reconstruction,
// plus the shadow-test confidence of Scherzer et al. 2007 (eq. 5) for accumulations.
#include "common/light.glsl"
#include "common/bias.glsl"

uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;

out vec2 o_visibility;  // r: visibility (1 = lit), g: confidence

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) {
    o_visibility = vec2(1.0, 0.0);
    return;
  }
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  float cosTheta = dot(N, directionToLight(P.xyz));
  if (cosTheta <= 0.0 || spotFactor(P.xyz) == 0.0) {
    o_visibility = vec2(0.0, 1.0);  // facing away or outside the cone: unlit whatever the map says
    return;
  }
  vec4 sc = layoutProject(biasReceiverPosition(P.xyz, N, cosTheta));
  if (sc.w == 0.0 || any(lessThan(sc.xy, vec2(0.0))) || any(greaterThan(sc.xy, vec2(1.0)))) {
    o_visibility = vec2(1.0, 0.0);  // outside the map: nothing there was rendered as a caster
    return;
  }
  float receiver = sc.z - biasDepth(P.xyz, cosTheta);
  float visibility = representationVisibility(sc.xy, receiver);
  vec2 texelPos = sc.xy * u_shadowMapSize;
  vec2 fromCenter = abs(texelPos - (floor(texelPos) + 0.5));
  float confidence = 1.0 - 2.0 * max(fromCenter.x, fromCenter.y);
  o_visibility = vec2(visibility, confidence);
}
