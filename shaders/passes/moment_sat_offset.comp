// The summed-area tables' offsets: per target the mean of the finite moments over the rows
// moment_sat_mean.comp summed (every layer), kept on the GPU, where the rows pass subtracts it
// and the lookups add it back (representations/prefiltered/moment_maps.glsl): nothing is read
// back to the CPU (a stall of the frame on a GPU). One invocation per target; the few hundred
// row sums are added with a compensated sum.
layout(local_size_x = 1) in;
uniform int u_rows;
layout(std430) readonly buffer RowSums {
  vec4 rowSum[];
};
layout(std430) readonly buffer RowCounts {
  vec4 rowCount[];
};
layout(std430) writeonly buffer SatOffsets {
  vec4 satOffset[];
};

void main() {
  int t = int(gl_GlobalInvocationID.x);
  if (t >= SL_MOMENT_TARGETS) return;
  precise vec4 sum = vec4(0.0), carry = vec4(0.0);
  vec4 count = vec4(0.0);
  for (int k = 0; k < u_rows; ++k) {
    precise vec4 y = rowSum[k * SL_MOMENT_TARGETS + t] - carry;
    precise vec4 s = sum + y;
    carry = (s - sum) - y;
    sum = s;
    count += rowCount[k * SL_MOMENT_TARGETS + t];
  }
  satOffset[t] = sum / max(count, vec4(1.0));
}
