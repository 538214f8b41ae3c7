// One direction of the separable box blur of every moment target, one layer. A box of width N
// texels: odd N has N equal taps; even N has N+1 taps with half weights at the ends, the exact
// area of a width-N box over nearest-neighbour texels (so every width keeps the texel centred).
#include "passes/moment_filter.glsl"
uniform vec2 u_direction;
uniform float u_width;

vec4 blurTarget(sampler2DArray src, ivec2 px) {
  int h = int(u_width) / 2;
  ivec2 dir = ivec2(u_direction);
  ivec2 last = textureSize(src, 0).xy - 1;
  TapSum s = tapSumBegin();
#ifdef SL_MOMENT_LOG_FILTER
  for (int i = -h; i <= h; ++i) s.big = tapMax(s.big, texelFetch(src, ivec3(clamp(px + dir * i, ivec2(0), last), u_layer), 0));
#endif
  for (int i = -h; i <= h; ++i)
    tapAdd(s, texelFetch(src, ivec3(clamp(px + dir * i, ivec2(0), last), u_layer), 0),
           clamp(0.5 * u_width + 0.5 - abs(float(i)), 0.0, 1.0));
  return tapSumEnd(s);
}

void main() {
  ivec2 px = ivec2(gl_FragCoord.xy);
  o_dst0 = blurTarget(u_src0, px);
#if SL_MOMENT_TARGETS > 1
  o_dst1 = blurTarget(u_src1, px);
#endif
#if SL_MOMENT_TARGETS > 2
  o_dst2 = blurTarget(u_src2, px);
#endif
#if SL_MOMENT_TARGETS > 3
  o_dst3 = blurTarget(u_src3, px);
#endif
#if SL_MOMENT_TARGETS > 4
  o_dst4 = blurTarget(u_src4, px);
#endif
#if SL_MOMENT_TARGETS > 5
  o_dst5 = blurTarget(u_src5, px);
#endif
#if SL_MOMENT_TARGETS > 6
  o_dst6 = blurTarget(u_src6, px);
#endif
#if SL_MOMENT_TARGETS > 7
  o_dst7 = blurTarget(u_src7, px);
#endif
}
