// Page marking of the virtual shadow map: each covered pixel counts itself on the page of the
// level its termination criterion asks for (layouts/virtual_request.glsl; a counter per page of
// every level, flat as PageAllocator's arrays): the counts decide which pages are coarsened
// first when the pool is too small.
// Criterion fitted (Giegl & Wimmer 2007) writes a grid over the light's view instead, read back
// and turned into a quadtree on the CPU (techniques/adaptive/quadtree_fit.h): per cell
// `levels - finest level asked for` (0: no sample) and the pixels that fell in it.
layout(local_size_x = 16, local_size_y = 16) in;
#include "layouts/virtual_common.glsl"
#include "layouts/virtual_request.glsl"
uniform sampler2D u_gPosition;
layout(std430) buffer PageMarks { uint marks[]; };
layout(std430) buffer FitGrid { uint fitGrid[]; };

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, textureSize(u_gPosition, 0)))) return;
  vec2 uv;
  int level = virtualRequestedLevel(u_gPosition, pixel, uv);
  if (level < 0) return;
  if (virtualCriterionIs(SL_VIRTUAL_CRITERION_FITTED)) {
    ivec2 cell = clamp(ivec2(floor(uv * float(SL_VIRTUAL_FIT_GRID))), ivec2(0), ivec2(SL_VIRTUAL_FIT_GRID - 1));
    int c = cell.y * SL_VIRTUAL_FIT_GRID + cell.x;
    atomicMax(fitGrid[c], uint(SL_VIRTUAL_LEVELS - level));
    atomicAdd(fitGrid[SL_VIRTUAL_FIT_GRID * SL_VIRTUAL_FIT_GRID + c], 1u);
    return;
  }
  int n = SL_VIRTUAL_PAGES >> level;
  ivec2 cell = clamp(ivec2(floor(uv * float(n))), ivec2(0), ivec2(n - 1));
  atomicAdd(marks[virtualLevelOffset(level) + cell.y * n + cell.x], 1u);
}
