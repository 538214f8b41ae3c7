// Irregular z-buffer, pass 2: exclusive prefix sum of the cell counts into offsets (cells + 1
// entries), in three steps (IZB_STEP) over chunks of kChunk cells, each walked by one invocation
// in order: 1. each chunk's total; 2. one invocation scans the totals; 3. each chunk's offsets
// from its total's offset. No shared memory and no barriers: llvmpipe runs a barrier by
// switching between its invocations, and the 256-wide tree scan with eight barriers cost it
// 5 ms a frame at 512² cells where these sequential walks cost under 1 (docs/performance.md).
layout(local_size_x = 64) in;
#include "passes/izb_common.glsl"
uniform int u_izbCells;
const uint kChunk = 1024u;  // cells per chunk; izb_state.cpp sizes blockSums by it

void main() {
  uint cells = uint(u_izbCells);
  uint chunks = (cells + kChunk - 1u) / kChunk;
#if IZB_STEP == 1
  uint chunk = gl_GlobalInvocationID.x;
  if (chunk >= chunks) return;
  uint end = min(cells, (chunk + 1u) * kChunk), sum = 0u;
  for (uint cell = chunk * kChunk; cell < end; ++cell) sum += counts[cell];
  blockSums[chunk] = sum;
#elif IZB_STEP == 2
  if (gl_GlobalInvocationID.x != 0u) return;
  uint running = 0u;
  for (uint chunk = 0u; chunk < chunks; ++chunk) {
    uint v = blockSums[chunk];
    blockSums[chunk] = running;
    running += v;
  }
  offsets[cells] = running;
  counters[1] += running;  // samples listed (this view's, added to the views' before)
#else
  uint chunk = gl_GlobalInvocationID.x;
  if (chunk >= chunks) return;
  uint end = min(cells, (chunk + 1u) * kChunk), running = blockSums[chunk];
  for (uint cell = chunk * kChunk; cell < end; ++cell) {
    offsets[cell] = running;
    running += counts[cell];
  }
#endif
}
