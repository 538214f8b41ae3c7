// One direction of the separable box blur of every moment target, one layer. Each invocation
// filters a run of SL_BLUR_RUN texels of one row (u_vertical = 0) or column (1): it fetches the
// run and its SL_BLUR_HALF-texel aprons once, instead of every output texel fetching all of its
// taps (a fragment pass did that; docs/performance.md has both measured).
// A box of width N texels: odd N has N equal taps; even N has N+1 taps with half weights at the
// ends, the exact area of a width-N box over nearest-neighbour texels (so every width keeps the
// texel centred). Edges clamp, as the texture's clamp-to-edge would.
#include "passes/moment_taps.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
uniform int u_layer;
uniform int u_vertical;
uniform float u_width;

const int kApron = SL_BLUR_HALF;
const int kWindow = SL_BLUR_RUN + 2 * kApron;

ivec3 texelAt(int along, int line) { return u_vertical == 1 ? ivec3(line, along, u_layer) : ivec3(along, line, u_layer); }

float tapWeight(int i) { return clamp(0.5 * u_width + 0.5 - abs(float(i)), 0.0, 1.0); }

// Filters the run of `line` of `src` that starts at `start` (texels past `last` clamp to it).
void blurRun(sampler2DArray src, int start, int line, int last, out vec4 result[SL_BLUR_RUN]) {
  vec4 window[kWindow];
  for (int i = 0; i < kWindow; ++i) window[i] = texelFetch(src, texelAt(clamp(start - kApron + i, 0, last), line), 0);
  for (int o = 0; o < SL_BLUR_RUN; ++o) {
    TapSum s = tapSumBegin();
#ifdef SL_MOMENT_LOG_FILTER
    for (int i = -kApron; i <= kApron; ++i) s.big = tapMax(s.big, window[o + kApron + i]);
#endif
    for (int i = -kApron; i <= kApron; ++i) tapAdd(s, window[o + kApron + i], tapWeight(i));
    result[o] = tapSumEnd(s);
  }
}

#define SL_BLUR_RUN_OF(src, dst)                                                   \
  {                                                                                \
    vec4 result[SL_BLUR_RUN];                                                      \
    blurRun(src, start, line, last, result);                                       \
    for (int o = 0; o < SL_BLUR_RUN && start + o <= last; ++o)                     \
      imageStore(dst, texelAt(start + o, line), result[o]);                        \
  }

uniform sampler2DArray u_src0;
layout(SL_BLUR_FORMAT0, binding = 0) writeonly uniform image2DArray u_dst0;
#if SL_MOMENT_TARGETS > 1
uniform sampler2DArray u_src1;
layout(SL_BLUR_FORMAT1, binding = 1) writeonly uniform image2DArray u_dst1;
#endif
#if SL_MOMENT_TARGETS > 2
uniform sampler2DArray u_src2;
layout(SL_BLUR_FORMAT2, binding = 2) writeonly uniform image2DArray u_dst2;
#endif
#if SL_MOMENT_TARGETS > 3
uniform sampler2DArray u_src3;
layout(SL_BLUR_FORMAT3, binding = 3) writeonly uniform image2DArray u_dst3;
#endif
#if SL_MOMENT_TARGETS > 4
uniform sampler2DArray u_src4;
layout(SL_BLUR_FORMAT4, binding = 4) writeonly uniform image2DArray u_dst4;
#endif
#if SL_MOMENT_TARGETS > 5
uniform sampler2DArray u_src5;
layout(SL_BLUR_FORMAT5, binding = 5) writeonly uniform image2DArray u_dst5;
#endif
#if SL_MOMENT_TARGETS > 6
uniform sampler2DArray u_src6;
layout(SL_BLUR_FORMAT6, binding = 6) writeonly uniform image2DArray u_dst6;
#endif
#if SL_MOMENT_TARGETS > 7
uniform sampler2DArray u_src7;
layout(SL_BLUR_FORMAT7, binding = 7) writeonly uniform image2DArray u_dst7;
#endif

void main() {
  int last = textureSize(u_src0, 0).x - 1;
  int start = int(gl_GlobalInvocationID.x) * SL_BLUR_RUN;
  int line = int(gl_GlobalInvocationID.y);
  if (start > last || line > last) return;
  SL_BLUR_RUN_OF(u_src0, u_dst0)
#if SL_MOMENT_TARGETS > 1
  SL_BLUR_RUN_OF(u_src1, u_dst1)
#endif
#if SL_MOMENT_TARGETS > 2
  SL_BLUR_RUN_OF(u_src2, u_dst2)
#endif
#if SL_MOMENT_TARGETS > 3
  SL_BLUR_RUN_OF(u_src3, u_dst3)
#endif
#if SL_MOMENT_TARGETS > 4
  SL_BLUR_RUN_OF(u_src4, u_dst4)
#endif
#if SL_MOMENT_TARGETS > 5
  SL_BLUR_RUN_OF(u_src5, u_dst5)
#endif
#if SL_MOMENT_TARGETS > 6
  SL_BLUR_RUN_OF(u_src6, u_dst6)
#endif
#if SL_MOMENT_TARGETS > 7
  SL_BLUR_RUN_OF(u_src7, u_dst7)
#endif
}
