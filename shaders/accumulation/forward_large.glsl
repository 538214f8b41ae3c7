// Forward shadow mapping's large splats: the texel pass (accumulation/forward_splat.comp)
// appends each splat of more than kInlinePixels pixels here instead of looping over it in one
// invocation (its SIMD lane-mates idle, the other core without work: thin-casters took 4 s);
// the rasterizer then draws each as a rectangle (accumulation/forward_splat_quad.*), spreading
// its pixels over every core. forwardLargeDraw is that draw's indirect command
// (accumulation/forward_splat_args.comp writes it).
struct ForwardLarge {
  // The texel (x | y << 16), the rectangle's first and last pixel (x | y << 16), and the depth
  // the texel stores (floatBitsToUint).
  uvec4 where;
};
layout(std430) buffer ForwardLargeSplats {
  uint forwardLargeCount;    // appended this frame (beyond the capacity: those were tested inline)
  uint forwardLargeDraw[4];  // vertices 6, instances, first 0, base instance 0
  ForwardLarge forwardLarge[];
};
uniform int u_largeCapacity;

uint packPair(ivec2 v) { return uint(v.x) | (uint(v.y) << 16); }
ivec2 unpackPair(uint v) { return ivec2(int(v & 0xffffu), int(v >> 16)); }
