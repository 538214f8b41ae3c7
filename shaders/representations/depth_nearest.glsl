// Nearest-texel depth test. receiverDepth already includes the bias; uvLayer.z is the layer.
#include "common/receiver_plane.glsl"
uniform sampler2DArray u_shadowMap;

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  float depth = receiverDepthAt(receiverDepth, uvLayer.xy, vec2(textureSize(u_shadowMap, 0).xy));
  return depth <= texture(u_shadowMap, uvLayer).r ? 1.0 : 0.0;
}

// How far from the receiver (in texels) the filter reads: scales the slope bias.
float representationFilterRadius(vec3 p, int view) { return 0.0; }
