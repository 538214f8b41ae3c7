// Irregular z-buffer, pass 4: caster triangles against the listed samples. A triangle covers
// the grid cells of its light-space bounds that its edges (widened by a hundredth of a cell
// against the rounding of the projection: the test below is exact, the cells only have to hold
// every candidate) do not exclude, walked as one span per row. Each listed sample of those cells is tested against the
// triangle itself: the ray from the sample's start toward the light hits it between the height
// tolerance and the light (Moller-Trumbore, as a ray tracer would), and an alpha-masked triangle
// only where its texture at the hit is opaque (nearest texel, repeat: the reference's filter).
// A hit sets the sample's bit (atomicOr).
// IZB_STEP 1: one invocation per triangle queues each row of its bounds whose span lists
// samples, one item per row. Walked here, a triangle kept the other lanes of its group waiting
// (a large one for the whole frame), and on llvmpipe lanes with nothing to test cost as much as
// busy ones: a group runs in step until its longest walk ends (Sponza: 190 + 100 ms with only
// triangles of more than 64 cells queued, 29 + 207 ms with all). IZB_STEP 2: writes the indirect
// dispatches of the queues. IZB_STEP 3: one invocation per queued row, run once per queue
// (IZB_QUEUE): alpha-masked triangles' rows have a queue of their own, the only one whose
// program has the alpha lookup.
// IZB_POSITIONAL (a light with a position) and IZB_MASKED (the scene has alpha-masked
// materials) are defines: llvmpipe runs a branch's code whatever the lanes take, so the alpha
// lookup cost every hit test in scenes with no mask (docs/performance.md).
layout(local_size_x = 64) in;
#include "passes/izb_common.glsl"
#include "common/ordered_bits.glsl"
uniform int u_izbTriangles;
uniform int u_izbQueueCapacity;
uniform vec3 u_lightDirection;  // a sun's rays go along its negation (izb_count.comp)
// Two queues of u_izbQueueCapacity items (triangle, row in its bounds), one after the other:
// the rows of triangles without an alpha mask, then those of masked ones. Their lengths are
// counters 2 and 5, their dispatches three words each.
layout(std430) buffer IzbQueue { uvec2 queue[]; };
layout(std430) buffer IzbDispatch { uint dispatchArgs[6]; };
uint queueLength(uint q) { return min(counters[q == 0u ? 2u : 5u], uint(u_izbQueueCapacity)); }

// floor(t * size) modulo size, in [0, size): GLSL's % is undefined for negative operands.
int wrapTexel(float t, int size) {
  int i = int(floor(t * float(size)));
  return i >= 0 ? i % size : size - 1 - (-(i + 1)) % size;
}

float alphaAt(Material m, Triangle t, float u, float v) {
  float alpha = m.alpha.y;
  int w = int(m.texture.y), h = int(m.texture.z);
  if (w <= 0 || h <= 0) return alpha;
  vec2 uv = (1.0 - u - v) * t.uv01.xy + u * t.uv01.zw + v * t.uv2.xy;
  int x = wrapTexel(uv.x, w), y = wrapTexel(uv.y, h);
  uint byteIndex = m.texture.x + uint(y * w + x);
  uint word = alphaBytes[byteIndex >> 2];
  return alpha * float((word >> (8u * (byteIndex & 3u))) & 255u) / 255.0;
}

struct Sample {
  vec4 origin;     // ray start; w: tnear
  vec4 direction;  // toward the light's centre; w: tfar
};

Sample sampleOf(uint pixel) {
  Sample s;
  s.origin = samples[kSampleVec4s * pixel];
#if IZB_POSITIONAL
  s.direction = samples[kSampleVec4s * pixel + 1u];
#else
  s.direction = vec4(-u_lightDirection, 1.0 / 0.0);
#endif
  return s;
}

// Ray from the sample toward the light against the triangle: hit strictly between tnear and
// tfar, barycentrics u (of b) and v (of c) for the alpha lookup.
bool hits(Sample s, vec3 a, vec3 e1, vec3 e2, out float u, out float v) {
  vec3 d = s.direction.xyz;
  vec3 p = cross(d, e2);
  float det = dot(e1, p);
  u = 0.0;
  v = 0.0;
  if (det == 0.0) return false;  // edge-on to the ray: no area to hit
  float inv = 1.0 / det;
  vec3 o = s.origin.xyz - a;
  u = dot(o, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  vec3 q = cross(o, e1);
  v = dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  float t = dot(e2, q) * inv;
  return t > s.origin.w && t < s.direction.w;
}

// What one triangle needs while it walks its cells.
struct Caster {
  uint id;
  Triangle t;
  Material m;
  bool masked;
  ivec2 lo, hi;    // cell bounds
  bool edges;      // the edge test below applies (projection known and not degenerate)
  uint nearBits;   // orderedBits of its smallest izbAwayKey, less a margin; 0: no cull (IzbCellState)
  vec3 edge[3];    // inward edge lines in grid units: dot(xy, 1) >= -margin inside
};

void growBounds(vec4 clip, inout vec2 lo, inout vec2 hi) {
  vec2 g = izbGridOf(clip);
  lo = min(lo, g);
  hi = max(hi, g);
}

// A triangle crossing the listed samples' w range under a directional light: the bounds of its
// part inside the range (the edges' points at the range's ends where they cross them, and the
// vertices inside). No edge spans: its projected edges are not those of the clipped part.
void clippedBounds(inout Caster c, vec4 v[3], float lo, float hi) {
  vec2 gmin = vec2(1e30), gmax = vec2(-1e30);
  for (int k = 0; k < 3; ++k) {
    vec4 p = v[k], q = v[(k + 1) % 3];
    if (p.w >= lo && p.w <= hi) growBounds(p, gmin, gmax);
    for (int end = 0; end < 2; ++end) {
      float plane = end == 0 ? lo : hi;
      if ((p.w - plane) * (q.w - plane) < 0.0) growBounds(mix(p, q, (plane - p.w) / (q.w - p.w)), gmin, gmax);
    }
  }
  c.lo = izbCell(gmin - 0.01);
  c.hi = izbCell(gmax + 0.01);
}

// The bounds and the three inward edge lines of a triangle wholly in front of the view.
void spanEdges(inout Caster c, vec4 v[3]) {
  vec2 g[3] = vec2[3](izbGridOf(v[0]), izbGridOf(v[1]), izbGridOf(v[2]));
  if (any(isnan(vec3(g[0].x + g[0].y, g[1].x + g[1].y, g[2].x + g[2].y)))) return;  // whole grid
  c.lo = izbCell(min(g[0], min(g[1], g[2])) - 0.01);
  c.hi = izbCell(max(g[0], max(g[1], g[2])) + 0.01);
  vec2 e1 = g[1] - g[0], e2 = g[2] - g[0];
  float area = e1.x * e2.y - e1.y * e2.x;
  c.edges = area != 0.0 && !isinf(area);
  float side = area > 0.0 ? 1.0 : -1.0;
  for (int k = 0; k < 3; ++k) {
    vec2 p = g[k], q = g[(k + 1) % 3];
    vec2 n = side * vec2(p.y - q.y, q.x - p.x);  // inward normal (unnormalized)
    // Inside (widened): dot(n, x - p) >= -0.01 * |n|.
    c.edge[k] = vec3(n, -dot(n, p) + 0.01 * length(n));
  }
}

bool setup(uint id, out Caster c) {
  c.id = id;
  c.t = triangles[id];
  c.m = materials[floatBitsToUint(c.t.c.w)];
  c.masked = c.m.texture.w != 0u;
  c.lo = ivec2(0);
  c.hi = ivec2(u_izbGrid - 1);
  c.edges = false;
  c.nearBits = 0u;
  // A masked material with no texture is all base alpha: below the cutoff it casts nothing.
  if (c.masked && c.m.texture.y == 0u && c.m.alpha.y < c.m.alpha.x) return false;
  vec4 v[3] = vec4[3](u_izbViewProj * vec4(c.t.a.xyz, 1.0), u_izbViewProj * vec4(c.t.b.xyz, 1.0),
                      u_izbViewProj * vec4(c.t.c.xyz, 1.0));
  vec3 w = vec3(v[0].w, v[1].w, v[2].w);
#if !IZB_POSITIONAL
  {
    // A directional light's views send a sample's ray to one point of the grid
    // (izb_state.cpp, raysProjectToPoints): clip w stays the sample's along it, so only a
    // triangle's part within the listed samples' w range can hit one (an orthographic view's w
    // is 1 throughout). The range is widened against the rounding of w between the passes.
    // IZB_W_RANGE: the grid's w varies (a warp); an orthographic grid's w is 1 everywhere,
    // where none of this can cull (izb_state.cpp).
#if IZB_W_RANGE
    float lo = max(uintBitsToFloat(~counters[3]) * (1.0 - 1e-5), 1e-6);
    float hi = uintBitsToFloat(counters[4]) * (1.0 + 1e-5);
    if (all(lessThan(w, vec3(lo))) || all(greaterThan(w, vec3(hi)))) return false;
    // Partly behind a warped view's centre of projection (casters behind the camera).
    if (any(lessThanEqual(w, vec3(1e-6)))) {
      clippedBounds(c, v, lo, hi);
      return true;
    }
#endif
  }
#else
  {
    // Wholly behind a perspective light's plane (w <= 0): no point of it lies between a listed
    // sample (w > 0) and the light (w = 0), where w falls linearly to 0.
    if (all(lessThanEqual(w, vec3(0.0)))) return false;
    // Partly behind it the projection wraps around: walk the whole grid.
    if (any(lessThanEqual(w, vec3(1e-6)))) return true;
  }
#endif
  spanEdges(c, v);
  // Wholly in front of the view: its key over it lies between its corners'. The margin (a
  // twenty-thousandth of the depth range, more for keys far outside it) keeps the rounding of
  // the two passes' projections from skipping a caster.
  float nearKey = min(izbAwayKey(v[0]), min(izbAwayKey(v[1]), izbAwayKey(v[2])));
  if (!isnan(nearKey)) c.nearBits = orderedBits(nearKey - 1e-4 * (1.0 + abs(nearKey)));
  return true;
}

// Cells [x0, x1] of row y that meet the widened triangle: per edge, the cells whose most
// inward corner is inside (the exact set the edge tests of each cell would keep, in O(1)).
bool rowSpan(Caster c, int y, out int x0, out int x1) {
  x0 = c.lo.x;
  x1 = c.hi.x;
  if (!c.edges) return true;
  float lo = float(c.lo.x), hi = float(c.hi.x);
  for (int k = 0; k < 3; ++k) {
    vec3 e = c.edge[k];
    float m = e.z + e.y * (float(y) + (e.y > 0.0 ? 1.0 : 0.0));  // the row's most inward y
    // Cell x passes when e.x * (x + (e.x > 0 ? 1 : 0)) + m >= 0.
    if (e.x > 0.0) lo = max(lo, ceil(-m / e.x - 1.0 - 1e-3));
    else if (e.x < 0.0) hi = min(hi, floor(m / -e.x + 1e-3));
    else if (m < 0.0) return false;
  }
  if (!(lo <= hi)) return false;  // NaN-safe
  x0 = int(lo);
  x1 = int(hi);
  return true;
}

void testCell(Caster c, ivec2 cellPos) {
  uint cell = uint(cellPos.y * u_izbGrid + cellPos.x);
  uint state = kCellWords * cell;
  if (c.nearBits > cellState[state]) return;       // wholly farther from the light than its samples
  if (cellState[state + 2u] == c.id + 1u) return;  // only its own samples
  uint begin = offsets[cell], end = min(offsets[cell + 1u], uint(u_izbCapacity));
  // Every sample occluded already: four in five of the samples Sponza's casters visited were.
  if (cellState[state + 1u] >= end - begin) return;
  vec3 a = c.t.a.xyz, e1 = c.t.b.xyz - a, e2 = c.t.c.xyz - a;
  for (uint k = begin; k < end; ++k) {
    uint pixel = list[k];
    uint bit = 1u << (pixel & 31u);
    if ((shadowBits[pixel >> 5] & bit) != 0u) continue;  // already occluded
    if (pixelCell[pixel].y == c.id) continue;  // its own triangle never shadows it
    Sample s = sampleOf(pixel);
    float u, v;
    if (!hits(s, a, e1, e2, u, v)) continue;
#if IZB_MASKED
    if (c.masked && alphaAt(c.m, c.t, u, v) < c.m.alpha.x) continue;
#endif
    if ((atomicOr(shadowBits[pixel >> 5], bit) & bit) == 0u) atomicAdd(cellState[state + 1u], 1u);
  }
}

// Cells are row-major: a span's samples are one range of the lists, empty more often than not.
bool rowHasSamples(Caster c, int y) {
  int x0, x1;
  if (!rowSpan(c, y, x0, x1)) return false;
  uint row = uint(y * u_izbGrid);
  return offsets[row + uint(x1) + 1u] != offsets[row + uint(x0)];
}

void testRow(Caster c, int y) {
  int x0, x1;
  if (!rowSpan(c, y, x0, x1)) return;
  uint row = uint(y * u_izbGrid);
  if (offsets[row + uint(x1) + 1u] == offsets[row + uint(x0)]) return;
  for (int x = x0; x <= x1; ++x) testCell(c, ivec2(x, y));
}

void main() {
#if IZB_STEP == 2
  for (uint q = 0u; q < 2u; ++q) {
    dispatchArgs[3u * q] = (queueLength(q) + 63u) / 64u;
    dispatchArgs[3u * q + 1u] = 1u;
    dispatchArgs[3u * q + 2u] = 1u;
  }
#elif IZB_STEP == 3
  if (gl_GlobalInvocationID.x >= queueLength(uint(IZB_QUEUE))) return;
  uint item = uint(IZB_QUEUE) * uint(u_izbQueueCapacity) + gl_GlobalInvocationID.x;
  // Slots a triangle reserved past a full queue hold older entries: testing them again is
  // harmless (the test is exact and only sets bits), reading past the triangles is not.
  if (queue[item].x >= uint(u_izbTriangles)) return;
  Caster c;
  setup(queue[item].x, c);
  int y = c.lo.y + int(queue[item].y);
  if (y <= c.hi.y) testRow(c, y);
#else
  uint id = gl_GlobalInvocationID.x;
  if (id >= uint(u_izbTriangles)) return;
  Caster c;
  if (!setup(id, c)) return;
  // Only rows whose span lists samples are queued (two loads per row to know).
  uint busy = 0u;
  for (int y = c.lo.y; y <= c.hi.y; ++y) busy += rowHasSamples(c, y) ? 1u : 0u;
  if (busy == 0u) return;
  uint q = c.masked ? 1u : 0u;
  uint slot = atomicAdd(counters[q == 0u ? 2u : 5u], busy);
  // A full queue is not an error: the triangle then walks its rows here, only slower.
  if (slot + busy <= uint(u_izbQueueCapacity)) {
    uint item = q * uint(u_izbQueueCapacity) + slot;
    for (int y = c.lo.y; y <= c.hi.y; ++y)
      if (rowHasSamples(c, y)) queue[item++] = uvec2(id, uint(y - c.lo.y));
    return;
  }
  for (int y = c.lo.y; y <= c.hi.y; ++y) testRow(c, y);
#endif
}
