// Shadow-map texels projected into the camera image as a checkerboard: large squares mean
// one texel covers many pixels (undersampling).
#include "common/light.glsl"
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform sampler2D u_gAlbedo;
out vec4 o_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) { o_color = vec4(0.1, 0.1, 0.12, 1.0); return; }
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  ShadowCoord c = layoutShadowCoord(P.xyz);
  vec4 sc = vec4(c.uv, c.depth, c.view >= 0 ? 1.0 : 0.0);
  float shade = 0.35 + 0.65 * max(dot(N, directionToLight(P.xyz)), 0.0);
  if (sc.w == 0.0 || any(lessThan(sc.xy, vec2(0.0))) || any(greaterThan(sc.xy, vec2(1.0)))) {
    o_color = vec4(vec3(0.3) * shade, 1.0);
    return;
  }
  ivec2 texel = ivec2(floor(sc.xy * u_shadowMapSize));
  float checker = float((texel.x + texel.y) & 1);
  vec3 a = vec3(0.95, 0.75, 0.3), b = vec3(0.25, 0.35, 0.75);
  o_color = vec4(pow(mix(a, b, checker) * shade, vec3(1.0 / 2.2)), 1.0);
}
