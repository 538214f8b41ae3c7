// Nearest-texel depth test. receiverDepth already includes the bias.
uniform sampler2D u_shadowMap;

float representationVisibility(vec2 uv, float receiverDepth) {
  return receiverDepth <= texture(u_shadowMap, uv).r ? 1.0 : 0.0;
}
