// Box PCF: the average of N x N nearest-texel tests around the receiver's texel.
#include "common/receiver_plane.glsl"
uniform sampler2DArray u_shadowMap;
uniform float u_pcf_kernel;

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  int n = int(u_pcf_kernel + 0.5);
  vec2 uv = uvLayer.xy;
  vec2 texel = 1.0 / vec2(textureSize(u_shadowMap, 0).xy);
  // Even kernels are centred between texels, odd ones on the receiver's texel.
  vec2 start = uv - texel * float(n - 1) * 0.5;
  vec4 range = lightViewTapRange(sl_view, 1.0 / texel);
  float lit = 0.0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      vec2 tap = lightViewTapIn(start + vec2(x, y) * texel, range);
      float depth = receiverDepthAt(receiverDepth, tap, 1.0 / texel);
      lit += depth <= texture(u_shadowMap, vec3(tap, uvLayer.z)).r ? 1.0 : 0.0;
    }
  return lit / float(n * n);
}

// How far from the receiver (in texels) the filter reads: scales the slope bias.
float representationFilterRadius(vec3 p, int view) { return 0.5 * (u_pcf_kernel - 1.0); }
