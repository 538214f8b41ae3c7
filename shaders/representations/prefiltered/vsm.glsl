// Variance shadow maps (Donnelly & Lauritzen 2006): moments (z, z^2), one-tailed Chebyshev
// bound, minimum variance, light-bleeding reduction.
#include "representations/prefiltered/moment_math.glsl"
uniform float u_vsm_min_variance;
uniform float u_vsm_bleed;

void representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS]) { m[0] = vec4(z, z * z, 0.0, 0.0); }

float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  return reduceLightBleeding(chebyshevUpperBound(m[0].xy, receiverDepth, u_vsm_min_variance), u_vsm_bleed);
}
// sigma^2 of the stored depths (the variance view).
float representationVariance(vec4 m[SL_MOMENT_TARGETS]) { return m[0].y - m[0].x * m[0].x; }
#include "representations/prefiltered/moment_maps.glsl"
