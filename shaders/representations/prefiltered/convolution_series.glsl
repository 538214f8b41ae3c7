// The Fourier series of the convolution shadow map (Annen et al. 2007; the notes' section 3),
// shared by `convolution` and `convolution-soft`: the step H(z - d) as
// 1/2 + 2 sum_k sin(c_k (z - d)) / c_k, c_k = (2k - 1) pi, truncated to M = SL_CONVOLUTION_TERMS
// terms. The map stores the basis images sin(c_k z), cos(c_k z) in channels 2k-2, 2k-1 (two
// terms per RGBA target), filtered linearly; the receiver weights them by cos(c_k d), -sin(c_k d).
// Terms are attenuated by exp(-alpha (k/M)^2) against ringing; the response is steepened (scale)
// about 1/2, the receiver moved toward the light (offset), and clamped to [0,1], which hides the
// remaining ringing.
// Depths enter as 0.9 z: the series is 2-periodic in z - d, and a receiver at d = 0 under an
// empty texel (z = 1) would sit on the period's jump (value 1/2); 0.9 keeps every difference
// inside (-1, 1) for offsets up to 0.11 (larger ones wrap only for receivers nearer than the
// offset to the light's near plane).
uniform float u_convolution_alpha;
uniform float u_convolution_scale;
uniform float u_convolution_offset;

const float kConvolutionSpan = 0.9;  // mirrored in techniques/prefiltered/prefiltered_representations.cpp

float momentChannel(vec4 m[SL_MOMENT_TARGETS], int c) { return m[c >> 2][c & 3]; }

float convolutionFrequency(int k) { return 3.14159265 * float(2 * k - 1); }

float convolutionAttenuation(int k) {
  float kM = float(k) / float(SL_CONVOLUTION_TERMS);
  return exp(-u_convolution_alpha * kM * kM);
}

// The receiver in the series' variable: 0.9 (d - offset), d clamped to the map's [0, 1] first.
// Under a grazing light the slope bias moves a receiver far in front of the light's near plane
// (a sun 0.05 degrees up: tan = 1146, several depth ranges); unclamped, d - z then leaves the
// period and wraps into shadow (convolution: 82 % false shadow there, issue #23). Every stored z
// is >= 0, so d = 0 already means "in front of all of them".
float convolutionReceiver(float receiverDepth) {
  return kConvolutionSpan * (clamp(receiverDepth, 0.0, 1.0) - u_convolution_offset);
}

// Writes sin(c_k u), cos(c_k u) of u = 0.9 z into channels 2k-2, 2k-1 (the rest untouched).
void convolutionBasis(float z, inout vec4 m[SL_MOMENT_TARGETS]) {
  float u = kConvolutionSpan * z;
  for (int k = 1; k <= SL_CONVOLUTION_TERMS; ++k) {
    float ck = convolutionFrequency(k);
    m[(2 * k - 2) >> 2][(2 * k - 2) & 3] = sin(ck * u);
    m[(2 * k - 1) >> 2][(2 * k - 1) & 3] = cos(ck * u);
  }
}

// sum_k 2 att_k / c_k (cos(c_k d) S_k - sin(c_k d) C_k) over the pair of channels holding S_k, C_k
// at `first` + 2k - 2: with the basis it is the filtered step minus 1/2; with the basis times u it
// is the filtered (step x u) minus half the mean u (CSM-Z).
float convolutionSum(vec4 m[SL_MOMENT_TARGETS], float d, int first) {
  float f = 0.0;
  for (int k = 1; k <= SL_CONVOLUTION_TERMS; ++k) {
    float ck = convolutionFrequency(k);
    float s = momentChannel(m, first + 2 * k - 2), c = momentChannel(m, first + 2 * k - 1);
    f += 2.0 * convolutionAttenuation(k) / ck * (cos(ck * d) * s - sin(ck * d) * c);
  }
  return f;
}

// The filtered step, unclamped (about the fraction of the kernel farther than the receiver).
float convolutionStep(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  return 0.5 + convolutionSum(m, convolutionReceiver(receiverDepth), 0);  // "don't forget to add 1/2"
}

// Steepened about 1/2 and clamped to [0,1].
float convolutionShape(float f) { return clamp(u_convolution_scale * (f - 0.5) + 0.5, 0.0, 1.0); }
