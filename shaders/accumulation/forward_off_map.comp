// Forward shadow mapping (Zhang 1998) lights what a light texel reaches; a pixel whose surface
// point falls outside the light view's map (beyond a point light's focused cone, behind a
// perspective light) no texel can reach, and the backward test calls it lit: nothing was
// rendered as a caster there (common/visibility_term.glsl). Marked lit before the splats, so
// forward mapping's holes are only those of its splats (beyond Zhang, whose light view holds the
// whole scene; street's lamp: 5.7 % -> see techniques/reconstruction/README.md).
#include "accumulation/forward_splat.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(vec2(pixel), u_screenSize))) return;
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) return;
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  vec3 F = gbufferFacetNormal(pixel, N);
  vec3 L = directionToLight(P.xyz);
  float cosTheta = dot(N, L);
  if (!surfaceFacesLight(P.xyz, N, F, L)) return;  // unlit, as the splats leave it
  ShadowCoord sc = layoutShadowCoordIn(biasReceiverPosition(P.xyz, N, cosTheta, 0), 0);
  if (shadowCoordOffMap(sc))
    imageStore(u_visibilityOut, pixel, vec4(1.0, 1.0, 0.0, 0.0));
}
