// Moment shadow maps (Peters & Klein 2015), Hamburger 4MSM: moments (z, z^2, z^3, z^4) of depth
// in [0,1], biased toward those of a uniform distribution (msm.moment_bias), Cholesky of the
// 3x3 Hankel matrix, the quadratic's two roots and the three-case bound. SL_MSM_QUANTIZED
// (msm16) stores the moments through the paper's optimized affine map, which spreads them over
// [0,1] so that 16 bits per moment suffice.
#include "representations/prefiltered/moment_math.glsl"
uniform float u_msm_moment_bias;

#ifdef SL_MSM_QUANTIZED
// Rows of the paper's matrix: stored = Q * b + (0.035955884801, 0, 0, 0), and its inverse.
const mat4 kMsmQuantize = mat4(-2.07224649, 13.7948857237, 0.105877704, 9.7924062118,
                               32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,
                               -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,
                               39.3703274134, -35.364903257, -6.6543490743, -23.9728048165);
const mat4 kMsmDequantize = mat4(0.2227744146, 0.1549679261, 0.1451988946, 0.163127443,
                                 0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266,
                                 0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497,
                                 0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734);
const vec4 kMsmOffset = vec4(0.035955884801, 0.0, 0.0, 0.0);
#endif

void representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS]) {
  float z2 = z * z;
  vec4 b = vec4(z, z2, z2 * z, z2 * z2);
#ifdef SL_MSM_QUANTIZED
  b = kMsmQuantize * b + kMsmOffset;
#endif
  m[0] = b;
}

// Shadow intensity (1 = fully shadowed) of the Hamburger bound: the paper's ComputeMSMHamburger.
float msmHamburger(vec4 b, float zf) {
  float l32d22 = -b.x * b.y + b.z;
  float d22 = max(-b.x * b.x + b.y, 1e-12);
  float squaredDepthVariance = -b.y * b.y + b.w;
  float d33d22 = max(dot(vec2(squaredDepthVariance, -l32d22), vec2(d22, l32d22)), 1e-24);
  float invD22 = 1.0 / d22;
  float l32 = l32d22 * invD22;
  vec3 c = vec3(1.0, zf, zf * zf);
  c.y -= b.x;
  c.z -= b.y + l32 * c.y;
  c.y *= invD22;
  c.z *= d22 / d33d22;
  c.y -= l32 * c.z;
  c.x -= dot(c.yz, b.xy);
  // A vanishing quadratic term (degenerate moments): no roots, fully lit by the bound.
  if (abs(c.z) < 1e-30) return 0.0;
  float p = c.y / c.z;
  float q = c.x / c.z;
  float r = sqrt(max(p * p * 0.25 - q, 0.0));
  float z1 = -p * 0.5 - r;
  float z2 = -p * 0.5 + r;
  vec4 s = z2 < zf ? vec4(z1, zf, 1.0, 1.0) : (z1 < zf ? vec4(zf, z1, 0.0, 1.0) : vec4(0.0));
  float denominator = (z2 - s.y) * (zf - z1);
  float quotient = abs(denominator) > 1e-30 ? (s.x * z2 - b.x * (s.x + z2) + b.y) / denominator : 0.0;
  return clamp(s.z + s.w * quotient, 0.0, 1.0);
}

float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  vec4 b = m[0];
#ifdef SL_MSM_QUANTIZED
  b = kMsmDequantize * (b - kMsmOffset);
#endif
  b = mix(b, vec4(0.5), u_msm_moment_bias);
  return 1.0 - msmHamburger(b, receiverDepth);
}
// sigma^2 of the stored depths (the variance view).
float representationVariance(vec4 m[SL_MOMENT_TARGETS]) {
  vec4 b = m[0];
#ifdef SL_MSM_QUANTIZED
  b = kMsmDequantize * (b - kMsmOffset);
#endif
  return b.y - b.x * b.x;
}
#include "representations/prefiltered/moment_maps.glsl"
