// Page marking of the virtual shadow map: each covered pixel counts itself on the page of the
// level its termination criterion asks for (layouts/virtual_request.glsl; a counter per page of
// every level, flat as PageAllocator's arrays): the counts decide which pages are coarsened
// first when the pool is too small.
layout(local_size_x = 16, local_size_y = 16) in;
#include "layouts/virtual_common.glsl"
#include "layouts/virtual_request.glsl"
uniform sampler2D u_gPosition;
layout(std430, binding = 4) buffer PageMarks { uint marks[]; };

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, textureSize(u_gPosition, 0)))) return;
  vec2 uv;
  int level = virtualRequestedLevel(u_gPosition, pixel, uv);
  if (level < 0) return;
  int n = SL_VIRTUAL_PAGES >> level;
  ivec2 cell = clamp(ivec2(floor(uv * float(n))), ivec2(0), ivec2(n - 1));
  atomicAdd(marks[virtualLevelOffset(level) + cell.y * n + cell.x], 1u);
}
