// The indirect draw of forward shadow mapping's large splats (accumulation/forward_large.glsl):
// one rectangle (6 vertices) per splat appended, within the buffer's capacity.
#include "accumulation/forward_large.glsl"
layout(local_size_x = 1) in;

void main() {
  forwardLargeDraw[0] = 6u;
  forwardLargeDraw[1] = min(forwardLargeCount, uint(u_largeCapacity));
  forwardLargeDraw[2] = 0u;
  forwardLargeDraw[3] = 0u;
}
