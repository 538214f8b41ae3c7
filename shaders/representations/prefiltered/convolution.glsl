// Convolution shadow maps (Annen et al. 2007; the notes' section 3): the step H(z - d) as the
// Fourier series 1/2 + 2 sum_k sin(c_k (z - d)) / c_k, c_k = (2k - 1) pi, truncated to
// M = SL_CONVOLUTION_TERMS terms. The map stores the basis images sin(c_k z), cos(c_k z)
// (term k in channels 2k-2, 2k-1: two terms per RGBA target), filtered linearly; the receiver
// weights them by cos(c_k d), -sin(c_k d). Terms are attenuated by exp(-alpha (k/M)^2) against
// ringing; the response is steepened (scale) about 1/2, the receiver moved toward the light
// (offset), and clamped to [0,1], which hides the remaining ringing.
// Depths enter as 0.9 z: the series is 2-periodic in z - d, and a receiver at d = 0 under an
// empty texel (z = 1) would sit on the period's jump (value 1/2); 0.9 keeps every difference
// inside (-1, 1) for offsets up to 0.11 (larger ones wrap only for receivers nearer than the
// offset to the light's near plane).
#include "representations/prefiltered/moment_math.glsl"
uniform float u_convolution_alpha;
uniform float u_convolution_scale;
uniform float u_convolution_offset;

const float kConvolutionSpan = 0.9;

void representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS]) {
  for (int t = 0; t < SL_MOMENT_TARGETS; ++t) m[t] = vec4(0.0);
  float u = kConvolutionSpan * z;
  for (int k = 1; k <= SL_CONVOLUTION_TERMS; ++k) {
    float ck = 3.14159265 * float(2 * k - 1);
    vec2 basis = vec2(sin(ck * u), cos(ck * u));
    if ((k & 1) == 1)
      m[(k - 1) / 2].xy = basis;
    else
      m[(k - 1) / 2].zw = basis;
  }
}

float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  float d = kConvolutionSpan * (receiverDepth - u_convolution_offset);
  float f = 0.5;  // "don't forget to add 1/2"
  for (int k = 1; k <= SL_CONVOLUTION_TERMS; ++k) {
    float ck = 3.14159265 * float(2 * k - 1);
    float kM = float(k) / float(SL_CONVOLUTION_TERMS);
    float attenuation = exp(-u_convolution_alpha * kM * kM);
    vec2 basis = (k & 1) == 1 ? m[(k - 1) / 2].xy : m[(k - 1) / 2].zw;  // sin, cos of c_k z
    f += 2.0 * attenuation / ck * (cos(ck * d) * basis.x - sin(ck * d) * basis.y);
  }
  return clamp(u_convolution_scale * (f - 0.5) + 0.5, 0.0, 1.0);
}
#include "representations/prefiltered/moment_maps.glsl"
