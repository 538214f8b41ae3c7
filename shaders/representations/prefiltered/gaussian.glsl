// Gaussian filtering (Gumbau et al. 2013): the VSM moments (z, z^2) read as a Gaussian, whose
// CDF gives the lit fraction instead of Chebyshev's bound.
#include "representations/prefiltered/moment_math.glsl"
#include "representations/prefiltered/receiver_spread.glsl"
uniform float u_gaussian_min_variance;

void representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS]) { m[0] = vec4(z, z * z, 0.0, 0.0); }

float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  float mean = storageMean(m[0].x);
  // The receiver's own plane over the box is not an occluder (receiver_spread.glsl).
  float variance = max(storageVariance(m[0].x, m[0].y) - receiverPlaneVariance(), u_gaussian_min_variance);
  return gaussianVisibility(receiverDepth, mean, variance);
}
// sigma^2 of the stored depths (the variance view).
float representationVariance(vec4 m[SL_MOMENT_TARGETS]) { return m[0].y - m[0].x * m[0].x; }
#include "representations/prefiltered/moment_maps.glsl"
