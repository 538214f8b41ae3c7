// Sums of the finite texels of each row of one layer of a moment target (and their count), for
// the mean that the summed-area table subtracts before summing (passes/moment_sat.comp).
layout(local_size_x = 64) in;
layout(SL_SAT_FORMAT, binding = 0) uniform readonly image2DArray satTable;
layout(std430) buffer RowSums {
  vec4 rowSum[];  // xyzw: sums; one per row of the layer
};
layout(std430) buffer RowCounts {
  vec4 rowCount[];
};
uniform int u_layer;
uniform int u_size;

void main() {
  int line = int(gl_GlobalInvocationID.x);
  if (line >= u_size) return;
  precise vec4 sum = vec4(0.0), count = vec4(0.0);
  for (int i = 0; i < u_size; ++i) {
    vec4 v = imageLoad(satTable, ivec3(i, line, u_layer));
    bvec4 finite = bvec4(vec4(not(isnan(v))) * vec4(not(isinf(v))));
    sum += mix(vec4(0.0), v, finite);
    count += vec4(finite);
  }
  rowSum[line] = sum;
  rowCount[line] = count;
}
