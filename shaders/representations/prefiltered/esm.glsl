// Exponential shadow maps (Annen et al. 2008): visibility exp(c (z_filtered - z_r)), where the
// map holds depth filtered in log space (log(sum w exp(c z)) / c, passes/moment_taps.glsl),
// so that exp(c z) is never stored and large c cannot overflow any format.
#include "representations/prefiltered/moment_math.glsl"
uniform float u_esm_exponent;

void representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS]) { m[0] = vec4(z, 0.0, 0.0, 0.0); }

float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  // min(., 0): receivers in front of the filtered occluder are lit; exp never overflows.
  return exp(min(u_esm_exponent * (m[0].x - receiverDepth), 0.0));
}
#include "representations/prefiltered/moment_maps.glsl"
