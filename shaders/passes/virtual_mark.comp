// Page marking of the virtual shadow map: each covered pixel of the G-buffer projects its
// footprint into the virtual map and counts itself on the page of the level that matches it
// (a counter per page of every level, flat as PageAllocator's arrays): the counts decide which
// pages are coarsened first when the pool is too small.
layout(local_size_x = 16, local_size_y = 16) in;
#include "layouts/virtual_common.glsl"
uniform sampler2D u_gPosition;
layout(std430, binding = 4) buffer PageMarks { uint marks[]; };

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, textureSize(u_gPosition, 0)))) return;
  float footprint = virtualFootprint(u_gPosition, pixel);
  if (footprint < 0.0) return;
  vec2 uv = virtualUv(texelFetch(u_gPosition, pixel, 0).xyz).xy;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return;
  int level = virtualLevelFor(footprint);
  int n = SL_VIRTUAL_PAGES >> level;
  ivec2 cell = clamp(ivec2(floor(uv * float(n))), ivec2(0), ivec2(n - 1));
  atomicAdd(marks[virtualLevelOffset(level) + cell.y * n + cell.x], 1u);
}
