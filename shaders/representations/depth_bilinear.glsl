// Hardware comparison with linear filtering: four depth tests blended bilinearly.
uniform sampler2DArrayShadow u_shadowMap;

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  return texture(u_shadowMap, vec4(uvLayer, receiverDepth));
}

// How far from the receiver (in texels) the filter reads: scales the slope bias.
float representationFilterRadius() { return 0.5; }
