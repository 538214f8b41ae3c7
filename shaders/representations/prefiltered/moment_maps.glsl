// Lookup side of the pre-filtered representations. A representation module defines
//   void  representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS])   (shadow pass)
//   float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth)
// and includes this file, which samples the filtered moment targets (bilinear, or trilinear at
// the mip level as wide as filter.width) and gives representationVisibility.
// SL_MOMENT_TARGETS, SL_MOMENT_FLOAT_BITS and SL_MOMENT_MIPMAP come from MomentMapState.
#ifdef SL_MOMENT_SOFT
const float u_filter_width = 1.0;  // soft ones size their boxes per pixel; views read single texels
#else
uniform float u_filter_width;
#endif
uniform sampler2DArray u_moments0;
#if SL_MOMENT_TARGETS > 1
uniform sampler2DArray u_moments1;
#endif
#if SL_MOMENT_TARGETS > 2
uniform sampler2DArray u_moments2;
#endif
#if SL_MOMENT_TARGETS > 3
uniform sampler2DArray u_moments3;
#endif
#if SL_MOMENT_TARGETS > 4
uniform sampler2DArray u_moments4;
#endif
#if SL_MOMENT_TARGETS > 5
uniform sampler2DArray u_moments5;
#endif
#if SL_MOMENT_TARGETS > 6
uniform sampler2DArray u_moments6;
#endif
#if SL_MOMENT_TARGETS > 7
uniform sampler2DArray u_moments7;
#endif

#ifdef SL_MOMENT_SAT
// Per target what its table subtracted before summing (the mean, passes/moment_sat_offset.comp),
// added back after the box's mean: a buffer the GPU wrote, so the CPU never reads it.
layout(std430) readonly buffer SatOffsets {
  vec4 satOffset[];
};

// The table at continuous texel position P: the integral of the (offset) moments over [0,P].
// The table read bilinearly is exactly that integral (piecewise bilinear per texel), with the
// table's texel (i, j) holding it at P = (i + 1, j + 1).
vec4 satAt(sampler2DArray table, vec2 P, vec2 n, float layer) {
  return textureLod(table, vec3((P - 0.5) / n, layer), 0.0);
}

// The table covers the texels visible receivers' boxes can reach (filter.skip_unread;
// moment_sat.cpp): corners are clamped to the rectangle around them, u_satBounds = (lo, hi) in
// texels. The table has no zero row or column before its first: boxes touching it shrink by up
// to a texel (the receivers' boxes never do; the rectangle holds their reach and more).
uniform vec4 u_satBounds;

// Mean over the box `width` texels wide centred on uv: four reads, whatever the width.
vec4 satBox(sampler2DArray table, vec4 offset, vec3 uvLayer, float width) {
  vec2 n = vec2(textureSize(table, 0).xy);
  vec2 c = uvLayer.xy * n;
  vec2 lo = clamp(c - 0.5 * width, u_satBounds.xy, u_satBounds.zw);
  vec2 hi = clamp(c + 0.5 * width, u_satBounds.xy, u_satBounds.zw);
  vec4 sum = satAt(table, hi, n, uvLayer.z) - satAt(table, vec2(lo.x, hi.y), n, uvLayer.z) -
             satAt(table, vec2(hi.x, lo.y), n, uvLayer.z) + satAt(table, lo, n, uvLayer.z);
  vec2 extent = hi - lo;
  return sum / max(extent.x * extent.y, 1e-6) + offset;
}
#endif

// The moments averaged over a box `width` texels wide (filter.width for the hard
// representations, a per-pixel width for the soft ones, which always filter by table).
void momentsInBox(vec3 uvLayer, float width, out vec4 m[SL_MOMENT_TARGETS]) {
#ifdef SL_MOMENT_MIPMAP
  // The level whose texels are filter.width texels of level 0 wide: every filter method then
  // averages over the same footprint (an explicit level: the visibility code is not in
  // uniform control flow, where screen-space derivatives would be undefined).
  float lod = log2(max(width, 1.0));
#else
  float lod = 0.0;
#endif
#ifdef SL_MOMENT_SAT
#define SL_MOMENT_FETCH(table, offset) satBox(table, offset, uvLayer, width)
#else
#define SL_MOMENT_FETCH(table, offset) textureLod(table, uvLayer, lod)
#endif
  m[0] = SL_MOMENT_FETCH(u_moments0, satOffset[0]);
#if SL_MOMENT_TARGETS > 1
  m[1] = SL_MOMENT_FETCH(u_moments1, satOffset[1]);
#endif
#if SL_MOMENT_TARGETS > 2
  m[2] = SL_MOMENT_FETCH(u_moments2, satOffset[2]);
#endif
#if SL_MOMENT_TARGETS > 3
  m[3] = SL_MOMENT_FETCH(u_moments3, satOffset[3]);
#endif
#if SL_MOMENT_TARGETS > 4
  m[4] = SL_MOMENT_FETCH(u_moments4, satOffset[4]);
#endif
#if SL_MOMENT_TARGETS > 5
  m[5] = SL_MOMENT_FETCH(u_moments5, satOffset[5]);
#endif
#if SL_MOMENT_TARGETS > 6
  m[6] = SL_MOMENT_FETCH(u_moments6, satOffset[6]);
#endif
#if SL_MOMENT_TARGETS > 7
  m[7] = SL_MOMENT_FETCH(u_moments7, satOffset[7]);
#endif
}

// The mean over a box two texels wide from the moments themselves (no table): over the
// nearest-texel map, a window one texel wide integrates to the bilinear read at its centre, so
// the box is the mean of four bilinear reads half a texel either side of uv, what a table's four
// corner reads give. The soft ones' only box under a point of light (MomentMapState::summed_), of
// the first SL_MOMENT_READ_TARGETS targets, what their reconstruction then reads (the others 0).
#ifndef SL_MOMENT_READ_TARGETS
#define SL_MOMENT_READ_TARGETS SL_MOMENT_TARGETS
#endif
void momentsInTwoTexelBox(vec3 uvLayer, out vec4 m[SL_MOMENT_TARGETS]) {
  vec2 halfTexel = 0.5 / vec2(textureSize(u_moments0, 0).xy);
  for (int t = 0; t < SL_MOMENT_TARGETS; ++t) m[t] = vec4(0.0);
  for (int k = 0; k < 4; ++k) {
    vec2 side = vec2((k & 1) == 0 ? -1.0 : 1.0, (k & 2) == 0 ? -1.0 : 1.0);
    vec3 at = vec3(uvLayer.xy + side * halfTexel, uvLayer.z);
    m[0] += 0.25 * textureLod(u_moments0, at, 0.0);
#if SL_MOMENT_READ_TARGETS > 1
    m[1] += 0.25 * textureLod(u_moments1, at, 0.0);
#endif
#if SL_MOMENT_READ_TARGETS > 2
    m[2] += 0.25 * textureLod(u_moments2, at, 0.0);
#endif
#if SL_MOMENT_READ_TARGETS > 3
    m[3] += 0.25 * textureLod(u_moments3, at, 0.0);
#endif
#if SL_MOMENT_READ_TARGETS > 4
    m[4] += 0.25 * textureLod(u_moments4, at, 0.0);
#endif
#if SL_MOMENT_READ_TARGETS > 5
    m[5] += 0.25 * textureLod(u_moments5, at, 0.0);
#endif
#if SL_MOMENT_READ_TARGETS > 6
    m[6] += 0.25 * textureLod(u_moments6, at, 0.0);
#endif
#if SL_MOMENT_READ_TARGETS > 7
    m[7] += 0.25 * textureLod(u_moments7, at, 0.0);
#endif
  }
}

void momentsAt(vec3 uvLayer, out vec4 m[SL_MOMENT_TARGETS]) { momentsInBox(uvLayer, max(u_filter_width, 1.0), m); }

// The box the hard representations filter over (prefiltered/receiver_spread.glsl declares it
// before its representation's code).
float filterBoxTexels() { return max(u_filter_width, 1.0); }

// The soft representations (prefiltered/soft_moments.glsl) size the box per pixel and define
// these two themselves.
#ifndef SL_MOMENT_SOFT
float representationVisibility(vec3 uvLayer, float receiverDepth) {
  vec4 m[SL_MOMENT_TARGETS];
  momentsAt(uvLayer, m);
  float v = representationFromMoments(m, receiverDepth);
  // Last line of defence only: the tests require representationFromMoments itself to be finite
  // and within [0,1] for every moment set the filters can produce.
  return isnan(v) ? 1.0 : clamp(v, 0.0, 1.0);
}

// Half the filter's footprint: the slope bias then covers the depth range of a tilted receiver
// across the kernel, as for PCF (the Gaussian CDF reads a receiver at its own mean depth as
// half shadowed without it).
float representationFilterRadius(vec3 p, int view) { return 0.5 * max(u_filter_width, 1.0); }
#endif
