// Exponentially warped Gaussian filtering (Gumbau et al. 2013, from the abstract: the method
// section was not available). The moments of the warped depth w = exp(c (2z - 1)) read as a
// Gaussian in w; the receiver's w against its CDF. The warp is monotonic, so the step of a
// single depth survives; it compresses the near occluders' spread relative to the far
// receiver's, which is what cuts the leaks. The variance floor is scaled by the warp's
// derivative (dw/dz = 2 c w), so it means the same depth spread at every depth.
// SL_WARP_MAX_EXPONENT (from the storage format) clamps c so that w^2 stays finite.
#include "representations/prefiltered/moment_math.glsl"
#include "representations/prefiltered/receiver_spread.glsl"
uniform float u_ewgf_exponent;
uniform float u_ewgf_min_variance;

float ewgfExponent() { return clamp(u_ewgf_exponent, 0.01, SL_WARP_MAX_EXPONENT); }

void representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS]) {
  float w = warpDepth(z, vec2(ewgfExponent())).x;
  m[0] = vec4(w, w * w, 0.0, 0.0);
}

float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  float c = ewgfExponent();
  float w = warpDepth(receiverDepth, vec2(c)).x;
  float mean = storageMean(m[0].x);
  float slope = 2.0 * c * w;
  // The receiver's own (warped) plane over the box is not an occluder (receiver_spread.glsl).
  float variance =
      max(storageVariance(m[0].x, m[0].y) - receiverPlaneWarpedVariance(c, mean), u_ewgf_min_variance * slope * slope);
  return gaussianVisibility(w, mean, variance);
}
// sigma^2 of the stored warped depths (the variance view: in warped units).
float representationVariance(vec4 m[SL_MOMENT_TARGETS]) { return m[0].y - m[0].x * m[0].x; }
#include "representations/prefiltered/moment_maps.glsl"
