// Final colour: albedo lit by the light times a visibility, plus ambient.
#include "common/light.glsl"

// Already display-encoded.
vec3 skyColor(float v) { return mix(vec3(0.80, 0.85, 0.92), vec3(0.42, 0.55, 0.75), v); }

// The light's direct term at P (before the albedo), in its colour: what a scene of several
// lights sums.
vec3 directLight(vec3 P, vec3 N, float vis) {
  return u_lightColor * (max(dot(N, directionToLight(P)), 0.0) * spotFactor(P) * clamp(vis, 0.0, 1.0));
}

// Magenta: a non-finite visibility or light sum must never pass silently.
const vec4 kNonFinite = vec4(1.0, 0.0, 1.0, 1.0);

vec4 shadeDirect(vec3 albedo, vec3 direct) {
  // Display encoding with gamma 2.0 (sqrt): on llvmpipe pow(x, 1/2.2) costs a sixth of the
  // frame at 1280x720 and the two differ by at most 0.03.
  return vec4(sqrt(albedo * (0.18 + 0.82 * direct)), 1.0);
}

vec4 shadeSurface(vec3 albedo, vec3 P, vec3 N, float vis) {
  if (isnan(vis) || isinf(vis)) return kNonFinite;
  return shadeDirect(albedo, directLight(P, N, vis));
}

#ifdef SL_DEFERRED
uniform sampler2D u_gAlbedo;

vec4 shadePixel(ivec2 pixel, vec3 P, vec3 N, float vis) {
  return shadeSurface(texelFetch(u_gAlbedo, pixel, 0).rgb, P, N, vis);
}
#endif
