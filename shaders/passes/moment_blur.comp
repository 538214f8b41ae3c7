// One direction of the separable box blur of every moment target, one layer. Each invocation
// filters a run of SL_BLUR_RUN texels of one row (u_vertical = 0) or column (1): it fetches the
// run and its SL_BLUR_HALF-texel aprons once, instead of every output texel fetching all of its
// taps (a fragment pass did that; docs/performance.md has both measured).
// SL_BLUR_FROM_DEPTH (the first direction): the source is the shadow pass's depth, turned into
// the representation's moments here, once per fetched texel. The shadow pass then writes depth
// alone, as a depth map's does, instead of every moment target for every caster fragment drawn.
// A box of 1 (no blur) takes the moments in a fragment pass instead (moment_from_depth.frag).
// A box of width N texels: odd N has N equal taps; even N has N+1 taps with half weights at the
// ends, the exact area of a width-N box over nearest-neighbour texels (so every width keeps the
// texel centred). Edges clamp, as the texture's clamp-to-edge would.
// The taps are finite, so they are summed without moment_taps.glsl's checks (which cost a tenth
// to a fifth of the pass on llvmpipe, as did a check once per fetched texel): the first
// direction takes a representation's moments of a sanitized depth, finite at every parameter
// (MomentMap.EveryRepresentationsMomentsStayFiniteAtItsExtremes), the second only the first's
// averages of those. ESM's log-space sum keeps its own path.
#include "passes/moment_taps.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
uniform int u_layer;
uniform int u_vertical;

const int kApron = SL_BLUR_HALF;
const int kWindow = SL_BLUR_RUN + 2 * kApron;

#ifdef SL_BLUR_FROM_DEPTH
uniform sampler2DArray u_depth;
#define SL_BLUR_SIZE_OF u_depth
#else
#define SL_BLUR_SIZE_OF u_src0
uniform sampler2DArray u_src0;
#if SL_MOMENT_TARGETS > 1
uniform sampler2DArray u_src1;
#endif
#if SL_MOMENT_TARGETS > 2
uniform sampler2DArray u_src2;
#endif
#if SL_MOMENT_TARGETS > 3
uniform sampler2DArray u_src3;
#endif
#if SL_MOMENT_TARGETS > 4
uniform sampler2DArray u_src4;
#endif
#if SL_MOMENT_TARGETS > 5
uniform sampler2DArray u_src5;
#endif
#if SL_MOMENT_TARGETS > 6
uniform sampler2DArray u_src6;
#endif
#if SL_MOMENT_TARGETS > 7
uniform sampler2DArray u_src7;
#endif
#endif

layout(SL_BLUR_FORMAT0, binding = 0) writeonly uniform image2DArray u_dst0;
#if SL_MOMENT_TARGETS > 1
layout(SL_BLUR_FORMAT1, binding = 1) writeonly uniform image2DArray u_dst1;
#endif
#if SL_MOMENT_TARGETS > 2
layout(SL_BLUR_FORMAT2, binding = 2) writeonly uniform image2DArray u_dst2;
#endif
#if SL_MOMENT_TARGETS > 3
layout(SL_BLUR_FORMAT3, binding = 3) writeonly uniform image2DArray u_dst3;
#endif
#if SL_MOMENT_TARGETS > 4
layout(SL_BLUR_FORMAT4, binding = 4) writeonly uniform image2DArray u_dst4;
#endif
#if SL_MOMENT_TARGETS > 5
layout(SL_BLUR_FORMAT5, binding = 5) writeonly uniform image2DArray u_dst5;
#endif
#if SL_MOMENT_TARGETS > 6
layout(SL_BLUR_FORMAT6, binding = 6) writeonly uniform image2DArray u_dst6;
#endif
#if SL_MOMENT_TARGETS > 7
layout(SL_BLUR_FORMAT7, binding = 7) writeonly uniform image2DArray u_dst7;
#endif

#ifdef SL_BLUR_GROUPS
// Only the work groups a visible receiver's lookups need run (techniques/prefiltered/
// blur_spans.h): the dispatch is a list, group k makes the runs of group tiles[u_groupOffset +
// k]. A group skipped by a branch would cost as much on llvmpipe, which runs every lane's side.
layout(std430) readonly buffer SlBlurGroups { uvec2 tiles[]; };
uniform int u_groupOffset;
uvec2 groupOrigin() { return tiles[u_groupOffset + int(gl_WorkGroupID.x)] * gl_WorkGroupSize.xy; }
#else
uvec2 groupOrigin() { return gl_WorkGroupID.xy * gl_WorkGroupSize.xy; }
#endif

// Every target's window: target t's texel i at g_window[t * kWindow + i].
vec4 g_window[SL_MOMENT_TARGETS * kWindow];

ivec3 texelAt(int along, int line) { return u_vertical == 1 ? ivec3(line, along, u_layer) : ivec3(along, line, u_layer); }

// SL_BLUR_WIDTH is a define, so that the weights fold into the unrolled sums.
float tapWeight(int i) { return clamp(0.5 * float(SL_BLUR_WIDTH) + 0.5 - abs(float(i)), 0.0, 1.0); }

// Fetches the run starting at `start` of `line` and its aprons (texels past the map clamp).
void fetchWindow(int start, int line, int last) {
  for (int i = 0; i < kWindow; ++i) {
    ivec3 at = texelAt(clamp(start - kApron + i, 0, last), line);
#ifdef SL_BLUR_FROM_DEPTH
    vec4 m[SL_MOMENT_TARGETS];
    representationMoments(sanitizeDepth(texelFetch(u_depth, at, 0).r), m);
    for (int t = 0; t < SL_MOMENT_TARGETS; ++t) g_window[t * kWindow + i] = m[t];
#else
    g_window[i] = texelFetch(u_src0, at, 0);
#if SL_MOMENT_TARGETS > 1
    g_window[kWindow + i] = texelFetch(u_src1, at, 0);
#endif
#if SL_MOMENT_TARGETS > 2
    g_window[2 * kWindow + i] = texelFetch(u_src2, at, 0);
#endif
#if SL_MOMENT_TARGETS > 3
    g_window[3 * kWindow + i] = texelFetch(u_src3, at, 0);
#endif
#if SL_MOMENT_TARGETS > 4
    g_window[4 * kWindow + i] = texelFetch(u_src4, at, 0);
#endif
#if SL_MOMENT_TARGETS > 5
    g_window[5 * kWindow + i] = texelFetch(u_src5, at, 0);
#endif
#if SL_MOMENT_TARGETS > 6
    g_window[6 * kWindow + i] = texelFetch(u_src6, at, 0);
#endif
#if SL_MOMENT_TARGETS > 7
    g_window[7 * kWindow + i] = texelFetch(u_src7, at, 0);
#endif
#endif
  }
}

// Target t's box average around the run's texel o.
vec4 filtered(int t, int o) {
  int centre = t * kWindow + o + kApron;
#ifdef SL_MOMENT_LOG_FILTER
  TapSum s = tapSumBegin();
  for (int i = -kApron; i <= kApron; ++i) s.big = tapMax(s.big, g_window[centre + i]);
  for (int i = -kApron; i <= kApron; ++i) tapAdd(s, g_window[centre + i], tapWeight(i));
  return tapSumEnd(s);
#else
  // Every tap finite, every tap present (edges clamp): the weights sum to the width.
  vec4 sum = vec4(0.0);
  for (int i = -kApron; i <= kApron; ++i) sum += g_window[centre + i] * tapWeight(i);
  return sum / float(SL_BLUR_WIDTH);
#endif
}

// Target t's run, filtered, into `dst` (both loops have constant bounds, so that the compiler
// unrolls them and the window stays in registers: llvmpipe indexes an array in memory otherwise).
#define SL_STORE_RUN(t, dst)                                                          \
  {                                                                                   \
    vec4 run[SL_BLUR_RUN];                                                            \
    for (int o = 0; o < SL_BLUR_RUN; ++o) run[o] = filtered(t, o);                    \
    for (int o = 0; o < SL_BLUR_RUN; ++o)                                             \
      if (start + o <= last) imageStore(dst, texelAt(start + o, line), run[o]);       \
  }

void main() {
  int last = textureSize(SL_BLUR_SIZE_OF, 0).x - 1;
  uvec2 id = groupOrigin() + gl_LocalInvocationID.xy;
  int start = int(id.x) * SL_BLUR_RUN;
  int line = int(id.y);
  if (start > last || line > last) return;
  fetchWindow(start, line, last);
  SL_STORE_RUN(0, u_dst0)
#if SL_MOMENT_TARGETS > 1
  SL_STORE_RUN(1, u_dst1)
#endif
#if SL_MOMENT_TARGETS > 2
  SL_STORE_RUN(2, u_dst2)
#endif
#if SL_MOMENT_TARGETS > 3
  SL_STORE_RUN(3, u_dst3)
#endif
#if SL_MOMENT_TARGETS > 4
  SL_STORE_RUN(4, u_dst4)
#endif
#if SL_MOMENT_TARGETS > 5
  SL_STORE_RUN(5, u_dst5)
#endif
#if SL_MOMENT_TARGETS > 6
  SL_STORE_RUN(6, u_dst6)
#endif
#if SL_MOMENT_TARGETS > 7
  SL_STORE_RUN(7, u_dst7)
#endif
}
