// PCSS step 1 as a pass of its own (techniques/soft/pcss.cpp): per covered G-buffer pixel, the
// average depth of the shadow-map texels closer to the light than the receiver within the region
// the area light sees it through, as receiver-to-blocker distance and penumbra radius (world
// units). Same view choice and bias as the visibility test (common/visibility_term.glsl).
#define SL_DEFERRED
#include "common/visibility_term.glsl"

uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
out vec4 o_blocker;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  o_blocker = vec4(0.0);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) return;
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  vec3 F = gbufferFacetNormal(pixel, N);
  vec3 L = directionToLight(P.xyz);
  float cosTheta = dot(N, L);
  // Unlit whatever the map holds (the visibility term decides these without the filter).
  if (cosTheta <= 0.0 || dot(F, L) <= 0.0 || spotFactor(P.xyz) == 0.0) return;
  ShadowCoord pick = layoutShadowCoord(P.xyz);
  if (pick.view < 0) return;
  int view = pick.view;
  ShadowCoord sc = layoutShadowCoordIn(biasReceiverPosition(P.xyz, N, cosTheta, view), view);
  if (sc.view < 0 || any(lessThan(sc.uv, vec2(0.0))) || any(greaterThan(sc.uv, vec2(1.0)))) return;
  float depth = sc.depth - biasDepth(P.xyz, cosTheta, view);
#if SL_BIAS_MODE == 4
  sl_receiverPlane = vec4(sc.uv, receiverPlaneGradient(P.xyz, F, view, sc));
#endif
  o_blocker = pcssBlockerSearch(vec3(sc.uv, float(view)), depth);
}
