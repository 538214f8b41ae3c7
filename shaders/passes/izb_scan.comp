// Irregular z-buffer, pass 2: exclusive prefix sum of the cell counts into offsets (cells + 1
// entries), in three steps (IZB_STEP): 1. each work group scans 1024 cells and writes its
// total; 2. one group scans the totals; 3. every cell adds its block's offset.
layout(local_size_x = 256) in;
#include "passes/izb_common.glsl"
uniform int u_izbCells;
shared uint partial[256];

// Exclusive scan of partial[] across the group; returns the group's total.
uint groupScan(uint value) {
  uint i = gl_LocalInvocationID.x;
  partial[i] = value;
  barrier();
  for (uint step = 1u; step < 256u; step <<= 1) {
    uint add = i >= step ? partial[i - step] : 0u;
    barrier();
    partial[i] += add;
    barrier();
  }
  uint total = partial[255];
  uint exclusive = partial[i] - value;
  barrier();
  partial[i] = exclusive;
  barrier();
  return total;
}

void main() {
  uint i = gl_LocalInvocationID.x;
#if IZB_STEP == 1
  uint base = gl_WorkGroupID.x * 1024u + i * 4u;
  uint v[4];
  uint sum = 0u;
  for (uint k = 0u; k < 4u; ++k) {
    v[k] = base + k < uint(u_izbCells) ? counts[base + k] : 0u;
    sum += v[k];
  }
  uint total = groupScan(sum);
  uint running = partial[i];
  for (uint k = 0u; k < 4u; ++k) {
    if (base + k < uint(u_izbCells)) offsets[base + k] = running;
    running += v[k];
  }
  if (i == 0u) blockSums[gl_WorkGroupID.x] = total;
#elif IZB_STEP == 2
  uint blocks = (uint(u_izbCells) + 1023u) / 1024u;
  uint per = (blocks + 255u) / 256u;
  uint sum = 0u;
  for (uint k = 0u; k < per; ++k) sum += i * per + k < blocks ? blockSums[i * per + k] : 0u;
  uint total = groupScan(sum);
  uint running = partial[i];
  for (uint k = 0u; k < per; ++k) {
    if (i * per + k >= blocks) break;
    uint v = blockSums[i * per + k];
    blockSums[i * per + k] = running;
    running += v;
  }
  if (i == 0u) {
    offsets[u_izbCells] = total;
    counters[1] += total;  // samples listed (this view's, added to the views' before)
  }
#else
  uint cell = gl_GlobalInvocationID.x;
  if (cell < uint(u_izbCells)) offsets[cell] += blockSums[cell / 1024u];
#endif
}
