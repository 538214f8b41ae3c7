// The receiver's own plane over the filter box, for the Gaussian reconstructions (gaussian,
// ewgf). Beyond the paper (Gumbau et al. read the filtered moments as the occluders' Gaussian): a
// tilted receiver sees its own depths spread over the box, and under a grazing light that spread
// is nearly all of the variance, so the CDF reads the receiver, which sits at the mean, as about
// half in shadow (ewgf: 85 % false shadow under a 0.5° sun, issue #23). The spread a plane with
// the receiver's gradient has over the box is taken out of the stored variance (never below the
// floor); what remains is the occluders'. Without a plane (views, the V plot) nothing changes.
#define SL_RECEIVER_PLANE_ALWAYS
#include "common/receiver_plane.glsl"
float filterBoxTexels();  // moment_maps.glsl

// Depth change of the receiver's plane from the box's centre to its edge along the map's u and v:
// over the box the plane is receiverDepth + s, s = k.x sx + k.y sy with sx, sy uniform in [-1, 1].
vec2 receiverHalfBoxSlope() {
  if (!(sl_receiverPlaneTexels > 0.0)) return vec2(0.0);
  return abs(sl_receiverPlane.zw) / sl_receiverPlaneTexels * (0.5 * filterBoxTexels());
}

// Var[s]: (k.x^2 + k.y^2) / 3.
float receiverPlaneVariance() {
  vec2 k = receiverHalfBoxSlope();
  return dot(k, k) / 3.0;
}

// sinh(x) / x, the mean of e^(x u) for u uniform in [-1, 1]; capped where the plane's spread is
// beyond anything a stored variance can hold anyway.
float sinhc(float x) {
  x = min(abs(x), 40.0);
  return x < 1e-3 ? 1.0 + x * x / 6.0 : sinh(x) / x;
}

// Var[w] of the warped plane w = exp(c (2 (z + s) - 1)) = wc e^(2 c s) over the box, wc its value
// at the box's centre: wc^2 (E[e^(4 c s)] - E[e^(2 c s)]^2), each expectation a product of sinhc
// per axis. wc from the plane's mean over the box, wc E[e^(2 c s)] = `mean` (the stored one: the
// receiver's own depth is biased towards the light, far below the plane's centre under a grazing
// light, where the warp's spread grows with the centre's value).
float receiverPlaneWarpedVariance(float c, float mean) {
  vec2 k = 2.0 * c * receiverHalfBoxSlope();
  float e1 = sinhc(k.x) * sinhc(k.y), e2 = sinhc(2.0 * k.x) * sinhc(2.0 * k.y);
  return mean * mean * max(e2 / (e1 * e1) - 1.0, 0.0);
}
