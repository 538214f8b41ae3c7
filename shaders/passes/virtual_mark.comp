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

#ifdef SL_VIRTUAL_CRITERION_IS_EDGES
// The edges criterion's 5x5 window of last frame's visibility (virtualNearShadowEdge), from a
// tile the group reads once (20x20 texels for its 16x16 pixels, clamped at the image's border as
// the per-pixel form is) and reduced along rows first: each pixel then combines five row
// entries instead of fetching 25 texels. The same answer: "some value differs from the centre
// by more than 0.25" is "the window's largest value exceeds the centre by more than 0.25, or the
// centre its smallest", with NaN values left out of both (they fail the comparison there too).
const int kEdgeApron = 2, kEdgeTile = 16 + 2 * kEdgeApron;
shared float edgeTile[kEdgeTile * kEdgeTile];
shared vec3 edgeRows[kEdgeTile * 16];  // per tile row and pixel column: min, max, 1 if a soft value

vec3 edgeWindowOf(vec3 a, float v) {
  bool soft = v > 0.02 && v < 0.98;
  return v == v ? vec3(min(a.x, v), max(a.y, v), max(a.z, soft ? 1.0 : 0.0)) : a;
}

bool nearShadowEdgeFromTile(ivec2 local) {
  ivec2 origin = ivec2(gl_WorkGroupID.xy) * 16 - kEdgeApron;
  ivec2 size = textureSize(u_previousVisibility, 0);
  uint first = gl_LocalInvocationIndex;
  for (uint i = first; i < uint(kEdgeTile * kEdgeTile); i += 256u) {
    ivec2 t = ivec2(int(i) % kEdgeTile, int(i) / kEdgeTile);
    edgeTile[i] = texelFetch(u_previousVisibility, clamp(origin + t, ivec2(0), size - 1), 0).x;
  }
  barrier();
  for (uint i = first; i < uint(kEdgeTile * 16); i += 256u) {
    int row = int(i) / 16, column = int(i) % 16;
    vec3 a = vec3(1e30, -1e30, 0.0);
    for (int x = 0; x < 5; ++x) a = edgeWindowOf(a, edgeTile[row * kEdgeTile + column + x]);
    edgeRows[i] = a;
  }
  barrier();
  vec3 a = vec3(1e30, -1e30, 0.0);
  for (int y = 0; y < 5; ++y) {
    vec3 r = edgeRows[(local.y + y) * 16 + local.x];
    a = vec3(min(a.x, r.x), max(a.y, r.y), max(a.z, r.z));
  }
  float centre = edgeTile[(local.y + kEdgeApron) * kEdgeTile + local.x + kEdgeApron];
  return u_hasPreviousVisibility == 0 || a.z > 0.5 || a.y - centre > 0.25 || centre - a.x > 0.25;
}
#endif

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
#ifdef SL_VIRTUAL_CRITERION_IS_EDGES
  bool edge = nearShadowEdgeFromTile(ivec2(gl_LocalInvocationID.xy));  // every invocation: barriers
#else
  const bool edge = false;
#endif
  if (any(greaterThanEqual(pixel, textureSize(u_gPosition, 0)))) return;
  vec2 uv;
  int level = virtualRequestedLevelNearEdge(u_gPosition, pixel, edge, uv);
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
