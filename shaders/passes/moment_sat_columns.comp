// The summed-area tables' second direction, in place: each invocation walks the rows of one
// column that its spans hold, through every target, turning the rows' running sums into the
// table (moment_sat_targets.glsl says why a box reads the same as from the whole map's table).
#define SL_SAT_ACCESS
#include "passes/moment_sat_targets.glsl"
layout(local_size_x = 64) in;
layout(std430) readonly buffer SatColumns {
  ivec2 rows[];  // per column of the map: the rows [y0, y1] whose span holds it
};

#define SL_SAT_ADD(t, table)                                                \
  kahanAdd(sum[t], carry[t], imageLoad(table, ivec3(column, j, u_layer))); \
  imageStore(table, ivec3(column, j, u_layer), sum[t]);

void main() {
  int column = u_rect.x + int(gl_GlobalInvocationID.x);
  if (column > u_rect.z) return;
  ivec2 r = rows[column];
  precise vec4 sum[SL_MOMENT_TARGETS], carry[SL_MOMENT_TARGETS];
  for (int t = 0; t < SL_MOMENT_TARGETS; ++t) sum[t] = carry[t] = vec4(0.0);
  for (int j = r.x; j <= r.y; ++j) {
    SL_SAT_EACH_TARGET(SL_SAT_ADD)
  }
}
