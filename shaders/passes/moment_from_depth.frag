// The representation's moments of each depth texel the shadow pass drew, one layer, as a
// fragment pass: the rasterizer's colour writes move the moments faster than a compute pass's
// image stores on llvmpipe. The representation's module comes first (prelude); the pass writes
// the first SL_MOMENT_WRITTEN_TARGETS targets (what is read: moment_filter.cpp).
uniform sampler2DArray u_depth;
uniform int u_layer;
layout(location = 0) out vec4 o_dst0;
#if SL_MOMENT_WRITTEN_TARGETS > 1
layout(location = 1) out vec4 o_dst1;
#endif
#if SL_MOMENT_WRITTEN_TARGETS > 2
layout(location = 2) out vec4 o_dst2;
#endif
#if SL_MOMENT_WRITTEN_TARGETS > 3
layout(location = 3) out vec4 o_dst3;
#endif
#if SL_MOMENT_WRITTEN_TARGETS > 4
layout(location = 4) out vec4 o_dst4;
#endif
#if SL_MOMENT_WRITTEN_TARGETS > 5
layout(location = 5) out vec4 o_dst5;
#endif
#if SL_MOMENT_WRITTEN_TARGETS > 6
layout(location = 6) out vec4 o_dst6;
#endif
#if SL_MOMENT_WRITTEN_TARGETS > 7
layout(location = 7) out vec4 o_dst7;
#endif

void main() {
  vec4 m[SL_MOMENT_TARGETS];
  representationMoments(sanitizeDepth(texelFetch(u_depth, ivec3(gl_FragCoord.xy, u_layer), 0).r), m);
  o_dst0 = m[0];
#if SL_MOMENT_WRITTEN_TARGETS > 1
  o_dst1 = m[1];
#endif
#if SL_MOMENT_WRITTEN_TARGETS > 2
  o_dst2 = m[2];
#endif
#if SL_MOMENT_WRITTEN_TARGETS > 3
  o_dst3 = m[3];
#endif
#if SL_MOMENT_WRITTEN_TARGETS > 4
  o_dst4 = m[4];
#endif
#if SL_MOMENT_WRITTEN_TARGETS > 5
  o_dst5 = m[5];
#endif
#if SL_MOMENT_WRITTEN_TARGETS > 6
  o_dst6 = m[6];
#endif
#if SL_MOMENT_WRITTEN_TARGETS > 7
  o_dst7 = m[7];
#endif
}
