// Box PCF: the average of N x N nearest-texel tests around the receiver's texel.
uniform sampler2D u_shadowMap;
uniform float u_pcf_kernel;

float representationVisibility(vec2 uv, float receiverDepth) {
  int n = int(u_pcf_kernel + 0.5);
  vec2 texel = 1.0 / vec2(textureSize(u_shadowMap, 0));
  // Even kernels are centred between texels, odd ones on the receiver's texel.
  vec2 start = uv - texel * float(n - 1) * 0.5;
  float lit = 0.0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      lit += receiverDepth <= texture(u_shadowMap, start + vec2(x, y) * texel).r ? 1.0 : 0.0;
  return lit / float(n * n);
}

// How far from the receiver (in texels) the filter reads: scales the slope bias.
float representationFilterRadius() { return 0.5 * (u_pcf_kernel - 1.0); }
