// The summed-area tables' targets as images (moment_sat_rows.comp, moment_sat_columns.comp):
// target t at binding t, its format SL_SAT_FORMATt; SL_SAT_ACCESS is the access qualifier.
// SL_SAT_EACH_TARGET(F) expands F(t, image) once per target, with constant t, so that the
// per-target arrays of the walks stay in registers (llvmpipe indexes arrays in memory otherwise).
layout(SL_SAT_FORMAT0, binding = 0) SL_SAT_ACCESS uniform image2DArray u_table0;
#if SL_MOMENT_TARGETS > 1
layout(SL_SAT_FORMAT1, binding = 1) SL_SAT_ACCESS uniform image2DArray u_table1;
#endif
#if SL_MOMENT_TARGETS > 2
layout(SL_SAT_FORMAT2, binding = 2) SL_SAT_ACCESS uniform image2DArray u_table2;
#endif
#if SL_MOMENT_TARGETS > 3
layout(SL_SAT_FORMAT3, binding = 3) SL_SAT_ACCESS uniform image2DArray u_table3;
#endif
#if SL_MOMENT_TARGETS > 4
layout(SL_SAT_FORMAT4, binding = 4) SL_SAT_ACCESS uniform image2DArray u_table4;
#endif
#if SL_MOMENT_TARGETS > 5
layout(SL_SAT_FORMAT5, binding = 5) SL_SAT_ACCESS uniform image2DArray u_table5;
#endif
#if SL_MOMENT_TARGETS > 6
layout(SL_SAT_FORMAT6, binding = 6) SL_SAT_ACCESS uniform image2DArray u_table6;
#endif
#if SL_MOMENT_TARGETS > 7
layout(SL_SAT_FORMAT7, binding = 7) SL_SAT_ACCESS uniform image2DArray u_table7;
#endif

#if SL_MOMENT_TARGETS == 1
#define SL_SAT_EACH_TARGET(F) F(0, u_table0)
#elif SL_MOMENT_TARGETS == 2
#define SL_SAT_EACH_TARGET(F) F(0, u_table0) F(1, u_table1)
#elif SL_MOMENT_TARGETS == 3
#define SL_SAT_EACH_TARGET(F) F(0, u_table0) F(1, u_table1) F(2, u_table2)
#elif SL_MOMENT_TARGETS == 4
#define SL_SAT_EACH_TARGET(F) F(0, u_table0) F(1, u_table1) F(2, u_table2) F(3, u_table3)
#elif SL_MOMENT_TARGETS == 5
#define SL_SAT_EACH_TARGET(F) F(0, u_table0) F(1, u_table1) F(2, u_table2) F(3, u_table3) F(4, u_table4)
#elif SL_MOMENT_TARGETS == 6
#define SL_SAT_EACH_TARGET(F) \
  F(0, u_table0) F(1, u_table1) F(2, u_table2) F(3, u_table3) F(4, u_table4) F(5, u_table5)
#elif SL_MOMENT_TARGETS == 7
#define SL_SAT_EACH_TARGET(F) \
  F(0, u_table0) F(1, u_table1) F(2, u_table2) F(3, u_table3) F(4, u_table4) F(5, u_table5) F(6, u_table6)
#else
#define SL_SAT_EACH_TARGET(F)                                                                       \
  F(0, u_table0) F(1, u_table1) F(2, u_table2) F(3, u_table3) F(4, u_table4) F(5, u_table5) F(6, u_table6) \
  F(7, u_table7)
#endif

// The table holds, in each row j, the texels span[j] = [x0, x1] that visible receivers' lookups
// read (an empty span: x0 > x1), and in each column x the rows column[x] = [y0, y1] whose span
// holds it (an interval: the spans are those of a convex region). Texel (x, y) holds the sum
// over the rows y0 <= j <= y of column x of the row's running sums from its span's start. A box
// whose corners lie in the spans sums to the same as in a table of the whole map: its two
// corners in a column share the rows above the box, which cancel, and in each row of the box
// both of its columns lie in the span, so their difference is the row's sum between them.
// u_rect: the columns (x) and rows (y) any span reaches.
uniform ivec4 u_rect;
uniform int u_layer;

// Kahan summation: each line's running sum exact to a few ulps over 2048 texels.
void kahanAdd(inout vec4 sum, inout vec4 carry, vec4 v) {
  precise vec4 y = v - carry;
  precise vec4 t = sum + y;
  carry = (t - sum) - y;
  sum = t;
}
