// The level of pages a covered G-buffer pixel asks for under the termination criterion
// (virtual.criterion): shared by the page-marking pass and the `requested-resolution` view, so
// the view shows what the criterion asked for, not the footprint alone.
// 0 footprint (resolution matching, Lefohn et al. 2007), 1 distance (tiled shadow maps' heuristic
// after Arvo 2004: the pixel's world size, as if every receiver faced the light, near the light
// depth's discontinuities; u_virtual_edge_coarsen levels coarser elsewhere), 2 edges
// (adaptive shadow maps, Fernando et al. 2001 / Lefohn et al. 2006: full resolution only near
// shadow edges, u_virtual_edge_coarsen levels coarser elsewhere; the edges are last frame's, so
// the first frame asks everywhere), 3 fitted (fitted virtual shadow maps, Giegl & Wimmer 2007:
// the footprint's level, gathered into a grid and fitted into a quadtree on the CPU). Needs
// layouts/virtual_common.glsl.
uniform float u_virtual_edge_coarsen;
uniform sampler2D u_previousVisibility;
uniform int u_hasPreviousVisibility;

// Level-0 texels of the pixel's world-space size (the step to its nearest neighbour on the
// surface) over the level-0 texel's world size: the footprint without the light's angle.
float virtualWorldFootprint(sampler2D gPosition, ivec2 pixel) {
  ivec2 size = textureSize(gPosition, 0);
  vec3 P = texelFetch(gPosition, pixel, 0).xyz;
  float best = 1e30;
  for (int k = 0; k < 4; ++k) {
    ivec2 q = pixel + ivec2(k == 0 ? 1 : k == 1 ? -1 : 0, k == 2 ? 1 : k == 3 ? -1 : 0);
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
    vec4 Q = texelFetch(gPosition, q, 0);
    if (Q.w > 0.5) best = min(best, length(Q.xyz - P));
  }
  return best < 1e29 ? best / lightViewRange[0].z : 1.0;
}

// Tiled shadow maps' depth-discontinuity term (Arvo 2004: tiles split "based on depth
// discontinuities, distances"): whether the light's depth around the point's position, in the
// finest page last frame drew there (3x3 texels of the atlas), bends or steps: the largest second
// difference along the rows, columns and diagonals over u_virtual_depth_step. A plane at any
// slope has none; a caster's silhouette, where shadow edges start, has one. The bend is kept per
// atlas texel (passes/virtual_depth_bend.comp, recomputed where pages are drawn). True where it
// cannot tell (no page yet, no bend, step 0): the pixel keeps its distance level there.
uniform sampler2D u_virtualDepthBend;
uniform int u_virtualHasDepthBend;
uniform float u_virtual_depth_step;

bool virtualNearDepthDiscontinuity(vec2 uv) {
  if (u_virtualHasDepthBend == 0 || !(u_virtual_depth_step > 0.0)) return true;
  VirtualPage page;
  if (!virtualFindPage(uv, page)) return true;
  ivec2 origin = ivec2(page.tile % SL_VIRTUAL_POOL_SIDE, page.tile / SL_VIRTUAL_POOL_SIDE) * SL_VIRTUAL_PAGE;
  ivec2 centre = clamp(ivec2(page.local * float(SL_VIRTUAL_PAGE)), ivec2(0), ivec2(SL_VIRTUAL_PAGE - 1));
  float bend = texelFetch(u_virtualDepthBend, origin + centre, 0).r;
  return !(bend <= u_virtual_depth_step);  // NaN from an undefined texel counts as a discontinuity
}

// Whether last frame's visibility changes within two pixels (a shadow edge passes here): some
// value of the 5x5 window around the pixel differs from the centre by more than 0.25, or lies
// strictly between 0.02 and 0.98. Read as nine gathers of 2x2 texels (6x6, the sixth row and
// column left out), clamped at the image's border (the texture clamps to its edge): "some value
// differs from the centre by more than 0.25" is "the window's largest value exceeds the centre by
// more than 0.25, or the centre its smallest", NaN values left out of both (they fail the
// comparison there too). 25 fetches per pixel, or a shared tile per work group with two
// barriers, cost the marking pass more (docs/performance.md).
vec3 virtualEdgeWindowWith(vec3 window, float v) {
  bool soft = v > 0.02 && v < 0.98;
  return v == v ? vec3(min(window.x, v), max(window.y, v), max(window.z, soft ? 1.0 : 0.0)) : window;
}

bool virtualNearShadowEdge(ivec2 pixel) {
  if (u_hasPreviousVisibility == 0) return true;
  vec2 size = vec2(textureSize(u_previousVisibility, 0));
  vec3 a = vec3(1e30, -1e30, 0.0);  // smallest, largest, 1 if a soft value
  float centre = 0.0;
  for (int gy = 0; gy < 3; ++gy)
    for (int gx = 0; gx < 3; ++gx) {
      // At texel corner k a gather reads texels k - 1 and k along each axis: pixel - 2 + 2 g and
      // the one after it. Components: w (x0, y0), z (x1, y0), x (x0, y1), y (x1, y1).
      vec4 g = textureGather(u_previousVisibility, vec2(pixel + ivec2(2 * gx - 1, 2 * gy - 1)) / size, 0);
      a = virtualEdgeWindowWith(a, g.w);
      if (gx < 2) a = virtualEdgeWindowWith(a, g.z);
      if (gy < 2) a = virtualEdgeWindowWith(a, g.x);
      if (gx < 2 && gy < 2) a = virtualEdgeWindowWith(a, g.y);
      if (gx == 1 && gy == 1) centre = g.w;
    }
  return a.z > 0.5 || a.y - centre > 0.25 || centre - a.x > 0.25;
}

// The level a pixel asks for under the criterion (the marking pass and the views); -1 when the
// pixel is not covered or falls off the map. uv: where it falls in the virtual map.
int virtualRequestedLevel(sampler2D gPosition, ivec2 pixel, out vec2 uv) {
  uv = vec2(-1.0);
  // The distance criterion replaces the footprint by the world size: only one of them is
  // computed (the criterion is a constant), the coverage test is the same.
  bool distance = virtualCriterionIs(SL_VIRTUAL_CRITERION_DISTANCE);
  float footprint = distance ? (virtualCovered(gPosition, pixel) ? virtualWorldFootprint(gPosition, pixel) : -1.0)
                             : virtualFootprint(gPosition, pixel);
  if (footprint < 0.0) return -1;
  uv = virtualUv(texelFetch(gPosition, pixel, 0).xyz).xy;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return -1;
  int level = virtualLevelFor(footprint);
  if ((virtualCriterionIs(SL_VIRTUAL_CRITERION_EDGES) && !virtualNearShadowEdge(pixel)) ||
      (distance && !virtualNearDepthDiscontinuity(uv)))
    level = min(level + int(u_virtual_edge_coarsen + 0.5), SL_VIRTUAL_LEVELS - 1);
  return level;
}
