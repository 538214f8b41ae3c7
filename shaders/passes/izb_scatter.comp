// Irregular z-buffer, pass 3: each listed sample takes the slot of its cell's range of the one
// index buffer that its rank in the count pass gives. Slots past the buffer's capacity do not exist: such a
// sample is counted as overflowed and flagged for the shadow-map test (no hang, no garbage).
layout(local_size_x = 8, local_size_y = 8) in;
#include "passes/izb_common.glsl"
layout(std430) readonly buffer IzbRank { uint pixelRank[]; };  // izb_count.comp

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, ivec2(u_izbSize)))) return;
  uint pixel = uint(px.y * int(u_izbSize.x) + px.x);
  uint cell = pixelCell[pixel].x;
  if (cell == kNoCell) return;
  uint slot = offsets[cell] + pixelRank[pixel];
  if (slot < uint(u_izbCapacity)) {
    list[slot] = pixel;
  } else {
    atomicOr(fallbackBits[pixel >> 5], 1u << (pixel & 31u));
    atomicAdd(counters[0], 1u);
  }
}
