// The tap average of the moment filters (the mip pass and the compute blur). ESM
// (SL_MOMENT_LOG_FILTER) stores depth and averages it as log(sum w exp(c z)) / c around the
// largest tap, so exp never sees a positive argument and no exponential is ever stored.
// Non-finite taps are dropped and the weights renormalized: one broken texel must not spread
// into a lit or black square.
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
