// One direction of a summed-area table of one moment target, in place: each invocation runs
// the prefix sum of one row (u_vertical = 0) or column (1) of one layer. The row pass first
// subtracts u_offset (the mean of the target's finite texels, moment_sat_mean.comp) so that the
// table's values, and the 32-bit sums of the box lookups, stay small; it also drops
// non-finite texels (they count as the offset). Kahan summation keeps each line's running sum
// exact to a few ulps.
layout(local_size_x = 64) in;
layout(SL_SAT_FORMAT, binding = 0) uniform image2DArray satTable;
uniform int u_layer;
uniform int u_vertical;
uniform int u_size;
uniform vec4 u_offset;

void main() {
  int line = int(gl_GlobalInvocationID.x);
  if (line >= u_size) return;
  precise vec4 sum = vec4(0.0), carry = vec4(0.0);
  for (int i = 0; i < u_size; ++i) {
    ivec3 p = u_vertical == 1 ? ivec3(line, i, u_layer) : ivec3(i, line, u_layer);
    vec4 v = imageLoad(satTable, p);
    if (u_vertical == 0) {
      bvec4 finite = bvec4(vec4(not(isnan(v))) * vec4(not(isinf(v))));
      v = mix(vec4(0.0), v - u_offset, finite);
    }
    precise vec4 y = v - carry;
    precise vec4 t = sum + y;
    carry = (t - sum) - y;
    sum = t;
    imageStore(satTable, p, sum);
  }
}
