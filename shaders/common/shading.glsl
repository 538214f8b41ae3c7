// Final colour from the G-buffer and a visibility: albedo lit by the light, plus ambient.
#include "common/light.glsl"

uniform sampler2D u_gAlbedo;

// Already display-encoded.
vec3 skyColor(float v) { return mix(vec3(0.80, 0.85, 0.92), vec3(0.42, 0.55, 0.75), v); }

vec4 shadePixel(ivec2 pixel, vec3 P, vec3 N, float vis) {
  // Non-finite visibility must never pass silently: magenta, so it is noticed.
  if (isnan(vis) || isinf(vis)) return vec4(1.0, 0.0, 1.0, 1.0);
  vec3 albedo = texelFetch(u_gAlbedo, pixel, 0).rgb;
  float direct = max(dot(N, directionToLight(P)), 0.0) * spotFactor(P) * clamp(vis, 0.0, 1.0);
  return vec4(pow(albedo * (0.18 + 0.82 * direct), vec3(1.0 / 2.2)), 1.0);
}
