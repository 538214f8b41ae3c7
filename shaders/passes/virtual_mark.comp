// Page marking of the virtual shadow map: each covered pixel of the G-buffer projects its
// footprint into the virtual map and counts itself on the page of the level that matches it
// (a counter per page of every level, flat as PageAllocator's arrays): the counts decide which
// pages are coarsened first when the pool is too small.
layout(local_size_x = 16, local_size_y = 16) in;
#include "layouts/virtual_common.glsl"
uniform sampler2D u_gPosition;
layout(std430, binding = 4) buffer PageMarks { uint marks[]; };
// The termination criterion (virtual.criterion): 0 footprint (resolution matching, Lefohn et al.
// 2007), 1 distance (tiled shadow maps' heuristic after Arvo 2004: the pixel's world size alone,
// as if every receiver faced the light), 2 edges (adaptive shadow maps, Fernando et al. 2001 /
// Lefohn et al. 2006: full resolution only near shadow edges, u_virtual_edge_coarsen levels
// coarser elsewhere; the edges are last frame's, so the first frame asks everywhere).
uniform float u_virtual_edge_coarsen;
uniform sampler2D u_previousVisibility;
uniform int u_hasPreviousVisibility;

// Level-0 texels of the pixel's world-space size (the step to its nearest neighbour on the
// surface) over the level-0 texel's world size: the footprint without the light's angle.
float worldFootprint(ivec2 pixel) {
  ivec2 size = textureSize(u_gPosition, 0);
  vec3 P = texelFetch(u_gPosition, pixel, 0).xyz;
  float best = 1e30;
  for (int k = 0; k < 4; ++k) {
    ivec2 q = pixel + ivec2(k == 0 ? 1 : k == 1 ? -1 : 0, k == 2 ? 1 : k == 3 ? -1 : 0);
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
    vec4 Q = texelFetch(u_gPosition, q, 0);
    if (Q.w > 0.5) best = min(best, length(Q.xyz - P));
  }
  return best < 1e29 ? best / lightViewRange[0].z : 1.0;
}

// Whether last frame's visibility changes within two pixels (a shadow edge passes here).
bool nearShadowEdge(ivec2 pixel) {
  if (u_hasPreviousVisibility == 0) return true;
  ivec2 size = textureSize(u_previousVisibility, 0);
  float centre = texelFetch(u_previousVisibility, clamp(pixel, ivec2(0), size - 1), 0).x;
  for (int y = -2; y <= 2; ++y)
    for (int x = -2; x <= 2; ++x) {
      float v = texelFetch(u_previousVisibility, clamp(pixel + ivec2(x, y), ivec2(0), size - 1), 0).x;
      if (abs(v - centre) > 0.25 || (v > 0.02 && v < 0.98)) return true;  // a step, or a soft edge
    }
  return false;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, textureSize(u_gPosition, 0)))) return;
  float footprint = virtualFootprint(u_gPosition, pixel);
  if (footprint < 0.0) return;
  vec2 uv = virtualUv(texelFetch(u_gPosition, pixel, 0).xyz).xy;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return;
  if (u_virtual_criterion > 0.5 && u_virtual_criterion < 1.5) footprint = worldFootprint(pixel);
  int level = virtualLevelFor(footprint);
  if (u_virtual_criterion > 1.5 && !nearShadowEdge(pixel))
    level = min(level + int(u_virtual_edge_coarsen + 0.5), SL_VIRTUAL_LEVELS - 1);
  int n = SL_VIRTUAL_PAGES >> level;
  ivec2 cell = clamp(ivec2(floor(uv * float(n))), ivec2(0), ivec2(n - 1));
  atomicAdd(marks[virtualLevelOffset(level) + cell.y * n + cell.x], 1u);
}
