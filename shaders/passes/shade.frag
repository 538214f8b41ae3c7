// Final colour: albedo lit by the light times the technique's visibility, plus ambient.
#include "common/light.glsl"

uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform sampler2D u_gAlbedo;
uniform sampler2D u_visibility;
in vec2 v_uv;
out vec4 o_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) {
    o_color = vec4(mix(vec3(0.80, 0.85, 0.92), vec3(0.42, 0.55, 0.75), v_uv.y), 1.0);
    return;
  }
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  vec3 albedo = texelFetch(u_gAlbedo, pixel, 0).rgb;
  float vis = texelFetch(u_visibility, pixel, 0).r;
  // Non-finite visibility must never reach the screen: show it as magenta so it is noticed.
  if (isnan(vis) || isinf(vis)) {
    o_color = vec4(1.0, 0.0, 1.0, 1.0);
    return;
  }
  float direct = max(dot(N, directionToLight(P.xyz)), 0.0) * spotFactor(P.xyz) * clamp(vis, 0.0, 1.0);
  vec3 linear = albedo * (0.18 + 0.82 * direct);
  o_color = vec4(pow(linear, vec3(1.0 / 2.2)), 1.0);
}
