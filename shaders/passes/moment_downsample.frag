// One mip level of every moment target, one layer: the 2x2 box average of the level above
// (the only level the source can sample during this draw: base = max level = source level).
#include "passes/moment_filter.glsl"

vec4 downsampleTarget(sampler2DArray src, ivec2 px) {
  ivec2 last = textureSize(src, 0).xy - 1;
  vec4 taps[4];
  TapSum s = tapSumBegin();
  for (int i = 0; i < 4; ++i) {
    taps[i] = texelFetch(src, ivec3(min(2 * px + ivec2(i & 1, i >> 1), last), u_layer), 0);
    s.big = tapMax(s.big, taps[i]);
  }
  for (int i = 0; i < 4; ++i) tapAdd(s, taps[i], 1.0);
  return tapSumEnd(s);
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  o_dst0 = downsampleTarget(u_src0, px);
#if SL_MOMENT_TARGETS > 1
  o_dst1 = downsampleTarget(u_src1, px);
#endif
#if SL_MOMENT_TARGETS > 2
  o_dst2 = downsampleTarget(u_src2, px);
#endif
#if SL_MOMENT_TARGETS > 3
  o_dst3 = downsampleTarget(u_src3, px);
#endif
#if SL_MOMENT_TARGETS > 4
  o_dst4 = downsampleTarget(u_src4, px);
#endif
#if SL_MOMENT_TARGETS > 5
  o_dst5 = downsampleTarget(u_src5, px);
#endif
#if SL_MOMENT_TARGETS > 6
  o_dst6 = downsampleTarget(u_src6, px);
#endif
#if SL_MOMENT_TARGETS > 7
  o_dst7 = downsampleTarget(u_src7, px);
#endif
}
