// Shared by the moment blur and mip passes: the source and destination targets (one layer) and
// the tap average. ESM (SL_MOMENT_LOG_FILTER) stores depth and averages it as
// log(sum w exp(c z)) / c around the largest tap, so exp never sees a positive argument and no
// exponential is ever stored. Non-finite taps are dropped and the weights renormalized: one
// broken texel must not spread into a lit or black square.
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
#ifdef SL_MOMENT_LOG_FILTER
uniform float u_logExponent;
#endif

// Componentwise "is finite". Selections below use mix(a, b, bvec4), which picks without
// arithmetic: mix with a float weight of 0 would still turn a NaN tap into NaN (NaN * 0).
bvec4 finite4(vec4 v) { return bvec4(vec4(not(isnan(v))) * vec4(not(isinf(v)))); }
vec4 finiteMask(vec4 v) { return vec4(finite4(v)); }

// A running weighted average. `big` is the largest finite tap (log filtering subtracts it).
struct TapSum {
  vec4 sum, weight, big;
};

TapSum tapSumBegin() { return TapSum(vec4(0.0), vec4(0.0), vec4(-1e30)); }

vec4 tapMax(vec4 big, vec4 v) { return max(big, mix(vec4(-1e30), v, finite4(v))); }

void tapAdd(inout TapSum s, vec4 v, float w) {
  vec4 ok = finiteMask(v) * w;
#ifdef SL_MOMENT_LOG_FILTER
  s.sum += ok * exp(u_logExponent * (mix(s.big, v, finite4(v)) - s.big));
#else
  s.sum += ok * mix(vec4(0.0), v, finite4(v));
#endif
  s.weight += ok;
}

vec4 tapSumEnd(TapSum s) {
  bvec4 any = greaterThan(s.weight, vec4(0.0));
#ifdef SL_MOMENT_LOG_FILTER
  // Nothing finite: depth 1, the far plane (no caster).
  return mix(vec4(1.0), s.big + log(max(s.sum / max(s.weight, vec4(1e-37)), vec4(1e-37))) / u_logExponent, any);
#else
  return mix(vec4(0.0), s.sum / max(s.weight, vec4(1e-37)), any);
#endif
}
