// Shared by the virtual layout module, its page-marking pass and its views: where a world point
// falls in the virtual map (light view 0 over the whole scene) and which mip level of pages the
// pixel footprint asks for. Defines from the layout state: SL_VIRTUAL_PAGES (pages per side at
// level 0, a power of two), SL_VIRTUAL_LEVELS (down to one page), SL_VIRTUAL_PAGE (texels per
// page side), SL_VIRTUAL_POOL_SIDE (tiles per side of the physical atlas), SL_VIRTUAL_FIT_GRID (cells per side
// of the fitted criterion's grid).
#include "common/light_views.glsl"
uniform float u_virtual_lod_bias;
// virtual.criterion's choice, a constant (the layout state's defines: SL_VIRTUAL_CRITERION_<CHOICE>
// the index of each declared choice, SL_VIRTUAL_CRITERION_IS_<CHOICE> the chosen one's flag).
#if defined(SL_VIRTUAL_CRITERION_IS_DISTANCE)
const int kVirtualCriterion = SL_VIRTUAL_CRITERION_DISTANCE;
#elif defined(SL_VIRTUAL_CRITERION_IS_EDGES)
const int kVirtualCriterion = SL_VIRTUAL_CRITERION_EDGES;
#elif defined(SL_VIRTUAL_CRITERION_IS_FITTED)
const int kVirtualCriterion = SL_VIRTUAL_CRITERION_FITTED;
#else
const int kVirtualCriterion = SL_VIRTUAL_CRITERION_FOOTPRINT;
#endif
bool virtualCriterionIs(int choice) { return choice == kVirtualCriterion; }

// Per page of level 0 the entry of the finest resident page over it, its level in bits 18..23
// (PageAllocator::finestTable()).
uniform usampler2D u_pageTable;

struct VirtualPage {
  int level;
  int tile;
  uint entry;  // page-table entry (tile + 1, drawn / needed bits, hits)
  vec2 local;  // position inside the page, [0,1]
};

// The finest resident page over virtual uv; false when none is (before the first allocation).
// One fetch at the level-0 page: the table names the finest page over it and its level.
bool virtualFindPage(vec2 uv, out VirtualPage page) {
  page = VirtualPage(-1, -1, 0u, vec2(0.0));
  ivec2 cell = clamp(ivec2(floor(uv * float(SL_VIRTUAL_PAGES))), ivec2(0), ivec2(SL_VIRTUAL_PAGES - 1));
  uint e = texelFetch(u_pageTable, cell, 0).r;
  if ((e & 0xffffu) == 0u) return false;
  int m = int((e >> 18) & 0x3fu);
  int n = SL_VIRTUAL_PAGES >> m;
  vec2 q = uv * float(n);
  // floor(uv n / 2^m) = floor(uv n) >> m: the level-m page over this cell.
  page = VirtualPage(m, int(e & 0xffffu) - 1, e, q - vec2(cell >> m));
  return true;
}

// Virtual uv in [0,1] (outside: off the map); z = 0 when the point cannot be projected.
vec3 virtualUv(vec3 worldPos) {
  vec4 c = lightViewProjMatrix[0] * vec4(worldPos, 1.0);
  if (!(c.w > 1e-6)) return vec3(0.0);
  return vec3(c.xy / c.w * 0.5 + 0.5, 1.0);
}

// Whether a G-buffer pixel holds a finite surface point the virtual map's view can project.
bool virtualCovered(sampler2D gPosition, ivec2 pixel) {
  vec4 P = texelFetch(gPosition, pixel, 0);
  if (P.w < 0.5 || any(isnan(P.xyz)) || any(isinf(P.xyz))) return false;
  return virtualUv(P.xyz).z != 0.0;
}

// Level-0 virtual texels one pixel spans at `pixel` of a G-buffer of world positions: the larger
// of its steps to the next pixel across and up, each taken on the side that stays on the
// surface (the smaller of left/right, down/up: a neighbour across a depth edge would ask for a
// needlessly coarse level). -1 when the pixel is not covered.
float virtualFootprint(sampler2D gPosition, ivec2 pixel) {
  ivec2 size = textureSize(gPosition, 0);
  if (!virtualCovered(gPosition, pixel)) return -1.0;
  vec3 uv = virtualUv(texelFetch(gPosition, pixel, 0).xyz);
  float steps[2];
  for (int axis = 0; axis < 2; ++axis) {
    float best = 1e30;
    for (int s = -1; s <= 1; s += 2) {
      ivec2 q = pixel + (axis == 0 ? ivec2(s, 0) : ivec2(0, s));
      if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
      vec4 Q = texelFetch(gPosition, q, 0);
      if (Q.w < 0.5) continue;
      vec3 uq = virtualUv(Q.xyz);
      if (uq.z == 0.0) continue;
      best = min(best, length(uq.xy - uv.xy));
    }
    steps[axis] = best;
  }
  float step = max(steps[0] < 1e29 ? steps[0] : steps[1], steps[1] < 1e29 ? steps[1] : steps[0]);
  if (!(step < 1e29)) return 1.0;  // an isolated pixel: ask for the finest level
  return step * float(SL_VIRTUAL_PAGES * SL_VIRTUAL_PAGE);
}

// The level whose texels are at most one pixel footprint (resolution matching), shifted by
// virtual.lod_bias (negative: finer).
int virtualLevelFor(float footprint) {
  float level = floor(log2(max(footprint, 1e-6)) + u_virtual_lod_bias);
  return int(clamp(level, 0.0, float(SL_VIRTUAL_LEVELS - 1)));
}

// Where a level's pages start in the flat arrays (PageAllocator::levelOffset).
int virtualLevelOffset(int level) {
  int offset = 0;
  for (int k = 0; k < level; ++k) offset += (SL_VIRTUAL_PAGES >> k) * (SL_VIRTUAL_PAGES >> k);
  return offset;
}

// Colours of the levels in the views: 0 red, 1 orange, 2 yellow, 3 green, 4 cyan, 5 blue,
// 6 purple, 7 and coarser grey.
vec3 virtualLevelColour(int level) {
  const vec3 palette[8] = vec3[8](vec3(0.90, 0.25, 0.20), vec3(0.95, 0.60, 0.20), vec3(0.95, 0.90, 0.30),
                                  vec3(0.35, 0.80, 0.30), vec3(0.30, 0.80, 0.85), vec3(0.25, 0.45, 0.95),
                                  vec3(0.65, 0.40, 0.85), vec3(0.60, 0.60, 0.60));
  return palette[clamp(level, 0, 7)];
}
