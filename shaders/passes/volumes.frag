// Participating media in the camera view (Scene::volumes): single scattering along each pixel's
// ray up to the opaque surface behind it, composited over the shaded colour (blend: ONE,
// SRC_ALPHA; out = medium colour weighted by its opacity, alpha = transmittance to the camera).
// Each march point is lit through the technique's own visibility, so what a technique knows
// about the medium shows: `deep` darkens the smoke's far side by its own transmittance, a depth
// map lets it glow. Needs the technique prelude (layout + representation modules).
#include "common/visibility_term.glsl"
#include "common/volume_density.glsl"

uniform sampler2D u_sceneDepth;  // the viewport's depth: 1 where nothing opaque was drawn
uniform mat4 u_invViewProj;
uniform vec3 u_cameraPosition;
in vec2 v_uv;
out vec4 o_color;

const int kMarchSteps = 48;      // as deep.volume_steps' default
const float kMediumAlbedo = 0.85;  // grey smoke: scattering over extinction

// The light reaching a point of the medium, as a surface facing the light would get it.
float mediumLight(vec3 P) {
#ifdef SL_PER_PIXEL_VISIBILITY
  // The representation decided visibility per G-buffer pixel (irregular z-buffer, PCSS's
  // blocker search): it has no answer at other points, so the medium is lit unshadowed.
  float visibility = 1.0;
#else
  vec3 L = directionToLight(P);
  vec4 coord;
  float visibility = visibilityTermAt(P, L, L, coord).x;
#endif
  return 0.18 + 0.82 * spotFactor(P) * clamp(visibility, 0.0, 1.0);
}

void main() {
  float depth = texelFetch(u_sceneDepth, ivec2(gl_FragCoord.xy), 0).r;
  vec4 end = u_invViewProj * vec4(v_uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  vec3 dir = end.xyz / end.w - u_cameraPosition;  // t in [0, 1] reaches the surface
  float t0 = 1.0, t1 = 0.0;
  for (int i = 0; i < volumeCount(); ++i) {
    float a, b;
    if (volumeRange(volumes[i], u_cameraPosition, dir, a, b)) {
      t0 = min(t0, a);
      t1 = max(t1, b);
    }
  }
  t0 = max(t0, 0.0);
  t1 = min(t1, 1.0);
  if (!(t1 > t0)) discard;
  float dt = (t1 - t0) / float(kMarchSteps), stepLength = dt * length(dir);
  float transmittance = 1.0, light = 0.0;
  for (int k = 0; k < kMarchSteps; ++k) {
    vec3 P = u_cameraPosition + (t0 + (float(k) + 0.5) * dt) * dir;
    float sigma = volumesExtinction(P);
    if (sigma <= 0.0) continue;
    float stepTransmittance = exp(-sigma * stepLength);
    light += transmittance * (1.0 - stepTransmittance) * kMediumAlbedo * mediumLight(P);
    transmittance *= stepTransmittance;
  }
  // A non-finite lookup must never pass silently: magenta, as shadeSurface does for a surface.
  if (isnan(light) || isinf(light)) {
    o_color = vec4(1.0, 0.0, 1.0, 0.0);
    return;
  }
  float opacity = 1.0 - transmittance;
  if (opacity < 1e-4) discard;
  // Blended in display encoding (sqrt, as shadeSurface), like most real-time compositing.
  o_color = vec4(vec3(sqrt(light / opacity) * opacity), transmittance);
}
