// The summed-area tables' first direction (Crow 1984; Hensley et al. 2005 for shadow maps): each
// invocation walks the span of one row, takes the representation's moments of each depth texel
// the shadow pass drew, subtracts the target's offset (the mean, moment_sat_offset.comp), drops
// non-finite moments (they count as the offset) and stores the running sums of every target.
// The shadow pass draws depth alone: no moments are written per caster fragment. The
// representation's module comes first (prelude).
#define SL_SAT_ACCESS writeonly
#include "passes/moment_taps.glsl"
#include "passes/moment_sat_targets.glsl"
layout(local_size_x = 64) in;
layout(std430) readonly buffer SatSpans {
  ivec2 span[];  // per row of the map
};
uniform sampler2DArray u_depth;
#ifndef SL_MOMENT_SAT  // else the module's lookups declared it (moment_maps.glsl)
layout(std430) readonly buffer SatOffsets {
  vec4 satOffset[];  // per target (moment_sat_offset.comp)
};
#endif

#define SL_SAT_ADD(t, table)                                                     \
  kahanAdd(sum[t], carry[t], mix(vec4(0.0), m[t] - satOffset[t], finite4(m[t]))); \
  imageStore(table, ivec3(i, line, u_layer), sum[t]);

void main() {
  int line = u_rect.y + int(gl_GlobalInvocationID.x);
  if (line > u_rect.w) return;
  ivec2 s = span[line];
  precise vec4 sum[SL_MOMENT_TARGETS], carry[SL_MOMENT_TARGETS];
  for (int t = 0; t < SL_MOMENT_TARGETS; ++t) sum[t] = carry[t] = vec4(0.0);
  for (int i = s.x; i <= s.y; ++i) {
    vec4 m[SL_MOMENT_TARGETS];
    representationMoments(sanitizeDepth(texelFetch(u_depth, ivec3(i, line, u_layer), 0).r), m);
    SL_SAT_EACH_TARGET(SL_SAT_ADD)
  }
}
