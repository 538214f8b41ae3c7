// Hardware comparison with linear filtering: four depth tests blended bilinearly.
#include "common/receiver_plane.glsl"
uniform sampler2DArrayShadow u_shadowMap;

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  float depth = receiverDepthForFootprint(receiverDepth, vec2(textureSize(u_shadowMap, 0).xy));
  return texture(u_shadowMap, vec4(uvLayer, depth));
}

// How far from the receiver (in texels) the filter reads: scales the slope bias.
float representationFilterRadius(vec3 p, int view) { return 0.5; }
