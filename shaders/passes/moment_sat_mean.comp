// The sums of every moment target over the finite moments of each u_meanStride-th row's span
// (and their count), taken from the shadow pass's depth: moment_sat_offset.comp turns them into
// the mean that the summed-area tables subtract before summing (moment_sat_rows.comp), so that
// their sums grow like a random walk instead of linearly with the texel count. Any offset near
// the mean serves: a quarter of the rows give it at a quarter of the cost. Each layer's rows go
// after the earlier layers' (u_rowBase). The representation's module comes first (prelude).
#include "passes/moment_taps.glsl"
layout(local_size_x = 64) in;
uniform sampler2DArray u_depth;
uniform ivec4 u_rect;
uniform int u_layer;
uniform int u_meanStride;
uniform int u_rowBase;  // the rows of earlier layers
layout(std430) readonly buffer SatSpans {
  ivec2 span[];  // per row of the map
};
layout(std430) buffer RowSums {
  vec4 rowSum[];  // sampled row k, target t: rowSum[k * SL_MOMENT_TARGETS + t]
};
layout(std430) buffer RowCounts {
  vec4 rowCount[];
};

void main() {
  int k = int(gl_GlobalInvocationID.x);
  int line = u_rect.y + k * u_meanStride;
  if (line > u_rect.w) return;
  vec4 sum[SL_MOMENT_TARGETS], count[SL_MOMENT_TARGETS];
  for (int t = 0; t < SL_MOMENT_TARGETS; ++t) sum[t] = count[t] = vec4(0.0);
  ivec2 s = span[line];
  for (int i = s.x; i <= s.y; ++i) {
    vec4 m[SL_MOMENT_TARGETS];
    representationMoments(sanitizeDepth(texelFetch(u_depth, ivec3(i, line, u_layer), 0).r), m);
    for (int t = 0; t < SL_MOMENT_TARGETS; ++t) {
      sum[t] += mix(vec4(0.0), m[t], finite4(m[t]));
      count[t] += finiteMask(m[t]);
    }
  }
  for (int t = 0; t < SL_MOMENT_TARGETS; ++t) {
    rowSum[(u_rowBase + k) * SL_MOMENT_TARGETS + t] = sum[t];
    rowCount[(u_rowBase + k) * SL_MOMENT_TARGETS + t] = count[t];
  }
}
