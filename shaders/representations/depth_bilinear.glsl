// Hardware comparison with linear filtering: four depth tests blended bilinearly.
uniform sampler2DShadow u_shadowMap;

float representationVisibility(vec2 uv, float receiverDepth) {
  return texture(u_shadowMap, vec3(uv, receiverDepth));
}
