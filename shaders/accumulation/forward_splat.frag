// Lights an eye pixel covered by a light sample's splat when the pixel shows the same surface:
// Zhang compares the two in the eye's depth buffer; here the pixel's surface point (G-buffer) is
// taken to the light view, where "the same surface" is exact on slopes too: the point falls in
// the sample's texel (forward.footprint texels) and is not behind the stored depth beyond the
// technique's bias, the test a backward map makes. Facing away: unlit, as everywhere.
#include "common/visibility_term.glsl"
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform float u_forward_footprint;
flat in vec3 v_sample;
flat in vec2 v_texel;
out vec2 o_visibility;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) discard;
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  vec3 F = gbufferFacetNormal(pixel, N);
  vec3 L = directionToLight(P.xyz);
  float cosTheta = dot(N, L);
  if (cosTheta <= 0.0 || dot(F, L) <= 0.0 || spotFactor(P.xyz) == 0.0) discard;
  ShadowCoord sc = layoutShadowCoordIn(biasReceiverPosition(P.xyz, N, cosTheta, 0), 0);
  if (sc.view < 0) discard;
  vec2 texelPos = sc.uv * float(textureSize(u_shadowMap, 0).x);
  if (any(greaterThan(abs(texelPos - v_texel), vec2(0.5 * u_forward_footprint)))) discard;
  float receiver = sc.depth - biasDepth(P.xyz, cosTheta, 0);
  float stored = layoutDepthIn(v_sample, 0);
  if (receiver > stored) discard;
  o_visibility = vec2(1.0, 1.0);
}
