// Deep shadow map lookup (Lokovic & Veach 2000): nearest depth test against the opaque casters
// times the transmittance of the semi-transparent ones, the piecewise-linear function of each of
// the 2x2 nearest deep texels interpolated in depth and the four filtered bilinearly. Without
// SL_DEEP (a scene with no semi-transparent casters) this is depth_nearest.glsl exactly.
#include "common/receiver_plane.glsl"
uniform sampler2DArray u_shadowMap;

#ifdef SL_DEEP
uniform sampler2DArray u_deepNodes;   // layer view * SL_DEEP_NODES + k: (depth, transmittance)
uniform sampler2DArray u_deepCounts;  // layer view: nodes used
// Per view: the window of the map uv the deep map covers (xy origin, zw size; deep_fit.h).
uniform vec4 u_deepWindow[SL_MAX_LIGHT_VIEWS];

float deepTexelTransmittance(ivec2 t, int view, float z) {
  int n = int(texelFetch(u_deepCounts, ivec3(t, view), 0).r + 0.5);
  if (n <= 0) return 1.0;
  vec2 prev = texelFetch(u_deepNodes, ivec3(t, view * SL_DEEP_NODES), 0).rg;
  if (z <= prev.x) return 1.0;
  for (int k = 1; k < SL_DEEP_NODES; ++k) {
    if (k >= n) break;
    vec2 cur = texelFetch(u_deepNodes, ivec3(t, view * SL_DEEP_NODES + k), 0).rg;
    if (z <= cur.x) return mix(prev.y, cur.y, clamp((z - prev.x) / max(cur.x - prev.x, 1e-12), 0.0, 1.0));
    prev = cur;
  }
  return prev.y;
}

float deepTransmittance(vec3 uvLayer, float z) {
  int view = sl_view;
  vec4 window = u_deepWindow[clamp(view, 0, SL_MAX_LIGHT_VIEWS - 1)];
  vec2 uv = (uvLayer.xy - window.xy) / window.zw;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;  // no deep caster there
  ivec2 size = textureSize(u_deepCounts, 0).xy;
  vec2 p = uv * vec2(size) - 0.5;
  vec2 f = p - floor(p);
  ivec2 i0 = ivec2(floor(p));
  float t[4];
  for (int k = 0; k < 4; ++k)
    t[k] = deepTexelTransmittance(clamp(i0 + ivec2(k & 1, k >> 1), ivec2(0), size - 1), view, z);
  return clamp(mix(mix(t[0], t[1], f.x), mix(t[2], t[3], f.x), f.y), 0.0, 1.0);
}
#endif

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  float depth = receiverDepthAt(receiverDepth, uvLayer.xy, vec2(textureSize(u_shadowMap, 0).xy));
  float visibility = depth <= texture(u_shadowMap, uvLayer).r ? 1.0 : 0.0;
#ifdef SL_DEEP
  if (visibility > 0.0) visibility *= deepTransmittance(uvLayer, receiverDepth);
#endif
  return visibility;
}

float representationFilterRadius(vec3 p, int view) { return 0.0; }
