// Nearest-texel depth test. receiverDepth already includes the bias.
uniform sampler2D u_shadowMap;

float representationVisibility(vec2 uv, float receiverDepth) {
  return receiverDepth <= texture(u_shadowMap, uv).r ? 1.0 : 0.0;
}

// How far from the receiver (in texels) the filter reads: scales the slope bias.
float representationFilterRadius() { return 0.0; }
