// Percentage-closer soft shadows (Fernando 2005) over any layout. The blocker search runs in its
// own screen-space pass (representations/soft/blocker_search.frag) and leaves per pixel, in
// u_pcssBlocker: x the receiver-to-blocker distance along the light, y the penumbra radius at the
// receiver, both world units (the same in every cascade), z 1 where it found a blocker. The test
// here converts the penumbra to texels of the view it reads and filters with a rotated Poisson
// disk of that radius. SL_AREA_LIGHT (renderer prelude, light.radius > 0) selects that path;
// without it the test is a minimum-kernel PCF (a point light has no penumbra).
#include "common/receiver_plane.glsl"
#include "representations/soft/poisson_disk.glsl"
#include "representations/soft/penumbra.glsl"
uniform sampler2DArray u_shadowMap;
uniform float u_pcss_blocker_samples;
uniform float u_pcss_filter_samples;
uniform float u_pcss_rotate;

mat2 pcssRotation() {
  float angle = u_pcss_rotate > 0.5 ? 6.2831853 * softNoise(gl_FragCoord.xy) : 0.0;
  return mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
}

// Fraction of Poisson taps within `radius` texels that the receiver passes.
float pcssFilter(vec3 uvLayer, float receiverDepth, float radius, int samples) {
  vec2 mapSize = vec2(textureSize(u_shadowMap, 0).xy);
  mat2 rot = pcssRotation();
  vec4 range = lightViewTapRange(sl_view, mapSize);
  float lit = 0.0;
  int n = clamp(samples, 1, kSoftPoissonCount);
  for (int i = 0; i < n; ++i) {
    vec2 tap = lightViewTapIn(uvLayer.xy + rot * kSoftPoisson[i] * radius / mapSize, range);
    float depth = receiverDepthAt(receiverDepth, tap, mapSize);
    lit += depth <= texture(u_shadowMap, vec3(tap, uvLayer.z)).r ? 1.0 : 0.0;
  }
  return lit / float(n);
}

// The same filter at the smallest kernel, kPcssMinRadius = 1 texel: every tap falls in one of the
// 3x3 texels around the receiver's, and a tap's test depends on its texel alone (its receiver
// depth is taken at the texel's centre, receiverDepthAt; the map is read nearest). So each of
// the nine texels is tested once and every tap counts its texel's answer: nine fetches instead
// of one per tap, the same fraction. Where the nine agree (most pixels: wholly lit or wholly in
// shadow) every tap does too and the taps are not visited (on llvmpipe they were half of
// `pcss`'s shading pass on basic).
float pcssFilterOneTexel(vec3 uvLayer, float receiverDepth, int samples) {
  vec2 mapSize = vec2(textureSize(u_shadowMap, 0).xy);
  vec4 range = lightViewTapRange(sl_view, mapSize);
  vec2 corner = floor(uvLayer.xy * mapSize) - 1.0;
  uint litTexels = 0u;
  for (int k = 0; k < 9; ++k) {
    vec2 texel = lightViewTapIn((corner + vec2(k % 3, k / 3) + 0.5) / mapSize, range);
    float depth = receiverDepthAt(receiverDepth, texel, mapSize);
    if (depth <= texture(u_shadowMap, vec3(texel, uvLayer.z)).r) litTexels |= 1u << uint(k);
  }
  if (litTexels == 0u) return 0.0;
  if (litTexels == 0x1ffu) return 1.0;
  mat2 rot = pcssRotation();
  float lit = 0.0;
  int n = clamp(samples, 1, kSoftPoissonCount);
  for (int i = 0; i < n; ++i) {
    vec2 tap = lightViewTapIn(uvLayer.xy + rot * kSoftPoisson[i] * kPcssMinRadius / mapSize, range);
    ivec2 t = clamp(ivec2(floor(tap * mapSize) - corner), ivec2(0), ivec2(2));
    lit += float((litTexels >> uint(t.y * 3 + t.x)) & 1u);
  }
  return lit / float(n);
}

// The blocker search: x receiver-to-blocker distance, y penumbra radius (world), z 1 = found,
// w the search radius (texels of this view).
vec4 pcssBlockerSearch(vec3 uvLayer, float receiverDepth) {
  int view = sl_view;
  vec2 mapSize = vec2(textureSize(u_shadowMap, 0).xy);
  float dR = pcssLinear(receiverDepth, view);
  float radius = pcssSearchTexels(view, dR);
  mat2 rot = pcssRotation();
  int n = clamp(int(u_pcss_blocker_samples + 0.5), 1, kSoftPoissonCount);
  vec4 range = lightViewTapRange(view, mapSize);
  float sum = 0.0, count = 0.0;
  for (int i = 0; i < n; ++i) {
    vec2 tap = lightViewTapIn(uvLayer.xy + rot * kSoftPoisson[i] * radius / mapSize, range);
    float stored = texture(u_shadowMap, vec3(tap, uvLayer.z)).r;
    if (stored < receiverDepthAt(receiverDepth, tap, mapSize)) {
      sum += stored;
      count += 1.0;
    }
  }
  if (count < 0.5) return vec4(0.0, 0.0, 0.0, radius);
  float dB = pcssLinear(sum / count, view);
  return vec4(max(dR - dB, 0.0), pcssPenumbraWorld(dR, dB), 1.0, radius);
}

#if defined(SL_AREA_LIGHT) && !defined(SL_PCSS_SEARCH_PASS)
// The blocker search ran at the G-buffer's samples only (shaders/passes/volumes.frag asks).
#define SL_PER_PIXEL_VISIBILITY
uniform sampler2D u_pcssBlocker;

vec4 pcssBlockerHere() { return texelFetch(u_pcssBlocker, ivec2(gl_FragCoord.xy), 0); }

// Filter radius (texels of `view`) of the penumbra found at this pixel.
float pcssRadiusTexels(vec4 b, int view, float receiverDepth) {
  float dR = pcssLinear(receiverDepth, view);
  float r = b.y / pcssTexelWorld(view, dR);
  // NaN fails every comparison: max/min keep a finite radius whatever came in.
  return isnan(r) ? kPcssMinRadius : clamp(r, kPcssMinRadius, u_pcss_max_radius);
}

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  vec4 b = pcssBlockerHere();
  // No blocker in the whole region the light can see the receiver through: fully lit.
  if (b.z < 0.5) return 1.0;
  int view = sl_view;
  return pcssFilter(uvLayer, receiverDepth, pcssRadiusTexels(b, view, receiverDepth), int(u_pcss_filter_samples + 0.5));
}

// The slope bias scales with how far the filter reads (receiver-plane bias is the presets' mode),
// in texels of the view the receiver reads (cascades: its own split's, not the first's).
float representationFilterRadius(vec3 p, int view) {
  vec4 b = pcssBlockerHere();
  float r = b.y / layoutTexelWorldSize(p, view);
  return b.z < 0.5 || isnan(r) ? kPcssMinRadius : clamp(r, kPcssMinRadius, u_pcss_max_radius);
}
#else
// Point light (or inside the search pass): a minimum-kernel PCF over the same disk.
float representationVisibility(vec3 uvLayer, float receiverDepth) {
  return pcssFilterOneTexel(uvLayer, receiverDepth, int(u_pcss_filter_samples + 0.5));
}
float representationFilterRadius(vec3 p, int view) { return kPcssMinRadius; }
#endif
