// The shadow term of one covered pixel: layout projection + representation reconstruction,
// plus the shadow-test confidence of Scherzer et al. 2007 (eq. 5) for accumulations.
// Needs the technique prelude (layout + representation modules).
#include "common/light.glsl"
#include "common/bias.glsl"

// x: visibility (1 = lit), y: confidence in [0,1] (1 = the sample sat on a texel centre).
vec2 visibilityTerm(vec3 P, vec3 N) {
  float cosTheta = dot(N, directionToLight(P));
  // Facing away or outside the cone: unlit whatever the map says (the reference agrees).
  if (cosTheta <= 0.0 || spotFactor(P) == 0.0) return vec2(0.0, 1.0);
  vec4 sc = layoutProject(biasReceiverPosition(P, N, cosTheta));
  // Outside the map nothing was rendered as a caster.
  if (sc.w == 0.0 || any(lessThan(sc.xy, vec2(0.0))) || any(greaterThan(sc.xy, vec2(1.0)))) return vec2(1.0, 0.0);
  float visibility = representationVisibility(sc.xy, sc.z - biasDepth(P, cosTheta));
  vec2 texelPos = sc.xy * u_shadowMapSize;
  vec2 fromCenter = abs(texelPos - (floor(texelPos) + 0.5));
  return vec2(visibility, 1.0 - 2.0 * max(fromCenter.x, fromCenter.y));
}

// True when the test gives `f` at the four shadow-map positions one texel diagonally around the
// receiver's: no rasterization (jitter) of this map could change the answer here.
bool visibilityUnambiguous(vec3 P, vec3 N, float f) {
  float cosTheta = dot(N, directionToLight(P));
  if (cosTheta <= 0.0 || spotFactor(P) == 0.0) return true;
  vec4 sc = layoutProject(biasReceiverPosition(P, N, cosTheta));
  if (sc.w == 0.0) return true;
  float depth = sc.z - biasDepth(P, cosTheta);
  float texel = 1.0 / u_shadowMapSize;
  for (int k = 0; k < 4; ++k) {
    vec2 offset = vec2(k & 1, k >> 1) * 2.0 - 1.0;
    vec2 uv = sc.xy + offset * texel;
    float v = any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) ? 1.0 : representationVisibility(uv, depth);
    if (abs(v - f) > 0.01) return false;
  }
  return true;
}
