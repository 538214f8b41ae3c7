// Soft shadows with convolution shadow maps (Annen et al. 2008; the notes' section 4), the PCSS
// steps (soft_moments.glsl) over the Fourier basis (convolution_series.glsl). CSM-Z: next to the
// 2M basis images the map stores them times the depth, u sin(c_k u) and u cos(c_k u), and u
// itself (u = 0.9 z); the complementary test 1 - f then averages the blockers' depth:
//   z_avg = E[(1 - f(d, z)) z] / E[1 - f(d, z)],
// both read from the same table box. Near a contact (small receiver-to-blocker gap) the
// filtered value is sharpened, s^p with p = 1 + A exp(-B gap), against the series' light leak.
// Channels: [0, 2M) basis, [2M, 4M) basis times u, 4M: u (4M + 1 <= 32: M <= 7).
#include "representations/prefiltered/moment_math.glsl"
#include "representations/prefiltered/convolution_series.glsl"
uniform float u_csmz_sharpen;
uniform float u_csmz_sharpen_falloff;

void representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS]) {
  for (int t = 0; t < SL_MOMENT_TARGETS; ++t) m[t] = vec4(0.0);
  convolutionBasis(z, m);
  const int M = SL_CONVOLUTION_TERMS;
  float u = kConvolutionSpan * z;
  for (int c = 0; c < 2 * M; ++c) m[(2 * M + c) >> 2][(2 * M + c) & 3] = u * momentChannel(m, c);
  m[(4 * M) >> 2][(4 * M) & 3] = u;
}

float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  return convolutionShape(convolutionStep(m, receiverDepth));
}

// CSM-Z: E[(1 - f) u] / E[1 - f] / 0.9 is the blockers' mean depth, with
// E[(1 - f) u] = E[u] / 2 - (the series over the basis-times-u channels). The truncated series
// also gives the receiver's own (lit) texels a weight w = 1 - f(offset), 0.3 to 0.45 at four terms,
// which pulls that mean toward the receiver and makes every lit pixel find "blockers". Beyond the
// paper: that weight is known (the series at the offset), so the blocked fraction is
// a = (E[1 - f] - w) / (1 - w) and the lit share's part, (1 - a) w u_receiver, is taken out of the
// weighted sum. For one planar blocker over a planar receiver this recovers the blocker's depth
// to within 0.01 at 4 terms where the bare estimate is off by 0.1 (the tests check both).
vec2 representationBlocker(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  const int M = SL_CONVOLUTION_TERMS;
  float d = convolutionReceiver(receiverDepth);
  float blockedRaw = 0.5 - convolutionSum(m, d, 0);
  float weighted = 0.5 * momentChannel(m, 4 * M) - convolutionSum(m, d, 2 * M);
  float selfWeight = 0.0;  // 1 - f of a texel at the receiver's own depth: 1/2 - the series at offset
  for (int k = 1; k <= M; ++k) {
    float ck = convolutionFrequency(k);
    selfWeight += 2.0 * convolutionAttenuation(k) / ck * sin(ck * kConvolutionSpan * u_convolution_offset);
  }
  selfWeight = clamp(0.5 - selfWeight, 0.0, 0.99);
  float a = clamp((blockedRaw - selfWeight) / (1.0 - selfWeight), 0.0, 1.0);
  float selfShare = (1.0 - a) * selfWeight;
  float blockerDepth = (weighted - selfShare * kConvolutionSpan * receiverDepth) / max(blockedRaw - selfShare, 1e-4);
  return vec2(a, blockerDepth / kConvolutionSpan);
}

float representationSoftVisibility(vec4 m[SL_MOMENT_TARGETS], float receiverDepth, float gap) {
  float s = representationFromMoments(m, receiverDepth);
  float p = 1.0 + u_csmz_sharpen * exp(-u_csmz_sharpen_falloff * max(gap, 0.0));
  return pow(s, p);
}
#include "representations/prefiltered/soft_moments.glsl"
