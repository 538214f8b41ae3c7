// PCF over a Poisson disk, optionally rotated per pixel by interleaved gradient noise.
#include "common/receiver_plane.glsl"
uniform sampler2DArray u_shadowMap;
uniform float u_poisson_samples;
uniform float u_poisson_radius;
uniform float u_poisson_rotate;

const vec2 kPoisson[32] = vec2[](
  vec2(-0.613392, 0.617481), vec2(0.170019, -0.040254), vec2(-0.299417, 0.791925), vec2(0.645680, 0.493210),
  vec2(-0.651784, 0.717887), vec2(0.421003, 0.027070), vec2(-0.817194, -0.271096), vec2(-0.705374, -0.668203),
  vec2(0.977050, -0.108615), vec2(0.063326, 0.142369), vec2(0.203528, 0.214331), vec2(-0.667531, 0.326090),
  vec2(-0.098422, -0.295755), vec2(-0.885922, 0.215369), vec2(0.566637, 0.605213), vec2(0.039766, -0.396100),
  vec2(0.751946, 0.453352), vec2(0.078707, -0.715323), vec2(-0.075838, -0.529344), vec2(0.724479, -0.580798),
  vec2(0.222999, -0.215125), vec2(-0.467574, -0.405438), vec2(-0.248268, -0.814753), vec2(0.354411, -0.887570),
  vec2(0.175817, 0.382366), vec2(0.487472, -0.063082), vec2(-0.084078, 0.898312), vec2(0.488876, -0.783441),
  vec2(0.470016, 0.217933), vec2(-0.696890, -0.549791), vec2(-0.149693, 0.605762), vec2(0.034211, 0.979980));

float interleavedGradientNoise(vec2 pixel) {
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  int n = clamp(int(u_poisson_samples + 0.5), 1, 32);
  vec2 uv = uvLayer.xy;
  vec2 texel = 1.0 / vec2(textureSize(u_shadowMap, 0).xy);
  float angle = u_poisson_rotate > 0.5 ? 6.2831853 * interleavedGradientNoise(gl_FragCoord.xy) : 0.0;
  mat2 rot = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
  vec4 range = lightViewTapRange(sl_view, 1.0 / texel);
  float lit = 0.0;
  for (int i = 0; i < n; ++i) {
    vec2 offset = rot * kPoisson[i] * u_poisson_radius * texel;
    vec2 tap = lightViewTapIn(uv + offset, range);
    float depth = receiverDepthAt(receiverDepth, tap, 1.0 / texel);
    lit += depth <= texture(u_shadowMap, vec3(tap, uvLayer.z)).r ? 1.0 : 0.0;
  }
  return lit / float(n);
}

// How far from the receiver (in texels) the filter reads: scales the slope bias.
float representationFilterRadius(vec3 p, int view) { return u_poisson_radius; }
