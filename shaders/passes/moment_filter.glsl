// The mip pass's source and destination targets (one layer) and the tap average
// (moment_taps.glsl, shared with the compute blur).
uniform int u_layer;
uniform sampler2DArray u_src0;
layout(location = 0) out vec4 o_dst0;
#if SL_MOMENT_TARGETS > 1
uniform sampler2DArray u_src1;
layout(location = 1) out vec4 o_dst1;
#endif
#if SL_MOMENT_TARGETS > 2
uniform sampler2DArray u_src2;
layout(location = 2) out vec4 o_dst2;
#endif
#if SL_MOMENT_TARGETS > 3
uniform sampler2DArray u_src3;
layout(location = 3) out vec4 o_dst3;
#endif
#if SL_MOMENT_TARGETS > 4
uniform sampler2DArray u_src4;
layout(location = 4) out vec4 o_dst4;
#endif
#if SL_MOMENT_TARGETS > 5
uniform sampler2DArray u_src5;
layout(location = 5) out vec4 o_dst5;
#endif
#if SL_MOMENT_TARGETS > 6
uniform sampler2DArray u_src6;
layout(location = 6) out vec4 o_dst6;
#endif
#if SL_MOMENT_TARGETS > 7
uniform sampler2DArray u_src7;
layout(location = 7) out vec4 o_dst7;
#endif
#include "passes/moment_taps.glsl"
