// Hardware comparison with linear filtering: four depth tests blended bilinearly.
uniform sampler2DShadow u_shadowMap;

float representationVisibility(vec2 uv, float receiverDepth) {
  return texture(u_shadowMap, vec3(uv, receiverDepth));
}

// How far from the receiver (in texels) the filter reads: scales the slope bias.
float representationFilterRadius() { return 0.5; }
