// Reconstruction formulas shared by the pre-filtered representations.

// Depths the moments are computed from: within [0,1]; NaN (a broken caster) counts as no caster.
float sanitizeDepth(float z) { return isnan(z) ? 1.0 : clamp(z, 0.0, 1.0); }

// One-tailed Chebyshev (Cantelli) bound on the lit fraction P(occluder depth >= t) from the
// mean and second moment: 1 when the receiver is nearer than the mean.
float chebyshevUpperBound(vec2 moments, float t, float minVariance) {
  float mean = moments.x;
  if (!(t > mean)) return 1.0;
  float variance = max(moments.y - mean * mean, minVariance);
  float d = t - mean;
  // var + d^2 > 0 unless both underflow; then the receiver is behind an exact occluder.
  return variance / max(variance + d * d, 1e-37);
}

// Light-bleeding reduction (Lauritzen): bounds below `amount` become shadow, the rest rescaled.
float reduceLightBleeding(float p, float amount) { return clamp((p - amount) / max(1.0 - amount, 1e-6), 0.0, 1.0); }

// erfc(x) by Abramowitz & Stegun 7.1.26 (absolute error of erf below 1.5e-7); for x < 0 through
// erfc(x) = 2 - erfc(-x), so both tails keep their relative accuracy.
float erfcApprox(float x) {
  float a = abs(x);
  float t = 1.0 / (1.0 + 0.3275911 * a);
  float poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
  float e = poly * exp(-a * a);
  return x >= 0.0 ? e : 2.0 - e;
}

// Lit fraction when the occluder depths are Gaussian with this mean and variance (Gumbau et al.):
// 1 - CDF(t) = erfc((t - mean) / (sigma sqrt 2)) / 2.
float gaussianVisibility(float t, float mean, float variance) {
  float sigma = sqrt(max(variance, 1e-37));
  return 0.5 * erfcApprox((t - mean) / (sigma * 1.41421356));
}

// What the storage format can tell apart (SL_MOMENT_FLOAT_BITS: 16 or 32). A stored moment m is
// rounded to within half an ulp, a relative 2^-11 in float16 (2^-24 in float32), so the mean of
// one planar occluder is off by up to that much, and m2 - m1^2 cancels to noise of about twice
// the ulp of m2. A Gaussian reads both literally: a receiver on its own occluder (d = mean) is
// half lit, and the noise variance makes a wide Gaussian out of a single depth. So a variance
// within the noise counts as none, and the receiver is compared with the mean moved back by
// its rounding error (a bias of exactly what the format cannot resolve).
#if SL_MOMENT_FLOAT_BITS == 16
const float kMomentRelativeUlp = 1.0 / 1024.0;
#else
const float kMomentRelativeUlp = 1.0 / 8388608.0;
#endif
float storageVariance(float m1, float m2) {
  float variance = m2 - m1 * m1;
  return variance > 2.0 * kMomentRelativeUlp * abs(m2) ? variance : 0.0;
}
float storageMean(float m1) { return m1 + 0.5 * kMomentRelativeUlp * abs(m1); }

// Positive and negative exponential warps of depth rescaled to [-1,1] (EVSM, EWGF).
vec2 warpDepth(float z, vec2 c) {
  float x = 2.0 * z - 1.0;
  return vec2(exp(c.x * x), -exp(-c.y * x));
}
