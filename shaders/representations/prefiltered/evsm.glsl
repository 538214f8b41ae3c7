// Exponential variance shadow maps: Chebyshev bounds on the moments of exp(c+ x) and
// -exp(-c- x), x = 2z - 1 in [-1,1]; SL_EVSM4 adds the negative warp and takes the smaller
// bound. SL_WARP_MAX_EXPONENT (from the storage format) clamps both exponents so that the
// squared moment stays finite; the variance floor is scaled by each warp's derivative.
#include "representations/prefiltered/moment_math.glsl"
uniform float u_evsm_exponent_pos;
uniform float u_evsm_min_variance;
uniform float u_evsm_bleed;
#ifdef SL_EVSM4
uniform float u_evsm_exponent_neg;
#endif

vec2 evsmExponents() {
#ifdef SL_EVSM4
  vec2 c = vec2(u_evsm_exponent_pos, u_evsm_exponent_neg);
#else
  vec2 c = vec2(u_evsm_exponent_pos, 1.0);
#endif
  return clamp(c, vec2(0.01), vec2(SL_WARP_MAX_EXPONENT));
}

void representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS]) {
  vec2 w = warpDepth(z, evsmExponents());
  m[0] = vec4(w.x, w.x * w.x, w.y, w.y * w.y);
}

float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  vec2 c = evsmExponents();
  vec2 w = warpDepth(receiverDepth, c);
  vec2 slope = 2.0 * c * w;  // d/dz of each warp
  float p = chebyshevUpperBound(m[0].xy, w.x, u_evsm_min_variance * slope.x * slope.x);
#ifdef SL_EVSM4
  p = min(p, chebyshevUpperBound(m[0].zw, w.y, u_evsm_min_variance * slope.y * slope.y));
#endif
  return reduceLightBleeding(p, u_evsm_bleed);
}
// sigma^2 of the positively warped depths (the variance view: in warped units).
float representationVariance(vec4 m[SL_MOMENT_TARGETS]) { return m[0].y - m[0].x * m[0].x; }
#include "representations/prefiltered/moment_maps.glsl"
