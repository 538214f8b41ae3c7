// Irregular z-buffer, pass 1: every covered pixel is an eye sample. Its ray start (on its own
// triangle's plane, with the reference's height tolerance: docs/reference.md), its direction to
// the light and its grid cell are stored, and the cell's count is incremented. Samples the
// reference calls unlit without tracing (facing away, terminator, outside the cone) get their
// shadow bit here and are not listed.
// Several light views (a point light's faces, cascades) run this pass once per view, each after
// the last view's triangles: a sample is listed in every view whose window holds it (a ray to
// the light stays inside a view that holds its start, so that view's casters are all its
// occluders) and its fallback bit, set for every pixel before the first view, is cleared once a
// view lists it or it is decided here; a sample in no window keeps the shadow-map test.
// IZB_POSITIONAL (a light with a position) and IZB_SEVERAL_VIEWS are defines, not uniforms:
// llvmpipe runs both sides of a branch whatever the lanes take, so code for the other kind of
// light cost every pixel (docs/performance.md, "Branches llvmpipe runs anyway").
#extension GL_ARB_gpu_shader_fp64 : enable
layout(local_size_x = 8, local_size_y = 8) in;
#include "passes/izb_common.glsl"
#include "common/ordered_bits.glsl"
// Each listed sample's place among its cell's (the count before it): the scatter pass needs no
// atomic of its own. Declared here and there alone: the triangles pass has no block to spare.
layout(std430) writeonly buffer IzbRank { uint pixelRank[]; };
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform usampler2D u_gSurface;
uniform vec3 u_lightDirection;
uniform vec3 u_lightPosition;
uniform float u_spotCosHalfAngle;
uniform int u_izbInstances;
uniform int u_izbTriangles;

double maxAbs(dvec3 v) { return max(abs(v.x), max(abs(v.y), abs(v.z))); }

// Under several views: this pixel needs no shadow-map test (decided here, or listed).
void decided(uint pixel) {
  if (IZB_SEVERAL_VIEWS != 0) atomicAnd(fallbackBits[pixel >> 5], ~(1u << (pixel & 31u)));
}

void setBit(uint pixel) {
  atomicOr(shadowBits[pixel >> 5], 1u << (pixel & 31u));
  decided(pixel);
}

// Lists the pixel's sample (its cell counted) and returns its clip w in the grid's view, or 0
// where it is decided here, off the grid or not covered.
float listSample() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(px, ivec2(u_izbSize)))) return 0.0;
  uint pixel = uint(px.y * int(u_izbSize.x) + px.x);
  pixelCell[pixel].x = kNoCell;
  vec4 P = texelFetch(u_gPosition, px, 0);
  if (!(P.w > 0.5)) {
    decided(pixel);
    return 0.0;
  }
  if (any(isnan(P.xyz)) || any(isinf(P.xyz))) { setBit(pixel); return 0.0; }
  vec3 n = texelFetch(u_gNormal, px, 0).xyz;
  uvec4 s = texelFetch(u_gSurface, px, 0);
  // Direction and distance to the light's centre, as the reference computes them (float).
  vec3 toLight = -u_lightDirection;
  float tfar = 1.0 / 0.0;
#if IZB_POSITIONAL
  {
    vec3 d = u_lightPosition - P.xyz;
    float dist = length(d);
    if (!(dist > 0.0)) { setBit(pixel); return 0.0; }
    toLight = d / dist;
    if (!(dot(-toLight, u_lightDirection) >= u_spotCosHalfAngle)) { setBit(pixel); return 0.0; }
    tfar = dist * (1.0 - 1e-4);
  }
#endif
  float nl = length(n);
  bool hasNormal = nl > 1e-12 && !isinf(nl);
  n = hasNormal ? n / nl : vec3(0.0);
  if (hasNormal && dot(n, toLight) <= 0.0) { setBit(pixel); return 0.0; }
  // The ray start on the exact plane of its triangle (in double, as the reference).
  dvec3 origin = dvec3(P.xyz);
  dvec3 plane = dvec3(n);
  bool hasPlane = hasNormal;
  double scale = maxAbs(origin);
  uint own = kNoCell;
  if (s.x > 0u && s.x <= uint(u_izbInstances)) own = instanceBase[s.x - 1u] + s.y;
  if (own < uint(u_izbTriangles)) {
    Triangle t = triangles[own];
    dvec3 a = dvec3(t.a.xyz), b = dvec3(t.b.xyz), c = dvec3(t.c.xyz);
    dvec3 f = cross(b - a, c - a);
    double len = length(f);
    if (len > 0.0 && floatBitsToUint(t.a.w) == s.x && floatBitsToUint(t.b.w) == s.y) {
      f /= len;
      if (hasPlane && dot(f, dvec3(n)) < 0.0) f = -f;
      origin = origin - f * dot(f, origin - a);
      plane = f;
      hasPlane = true;
      scale = max(max(maxAbs(origin), maxAbs(a)), max(maxAbs(b), maxAbs(c)));
    }
  }
  if (hasPlane && dot(plane, dvec3(toLight)) <= 0.0) { setBit(pixel); return 0.0; }  // terminator
  double tolerance = max(scale / 1048576.0, 1e-9);
  double tnear = hasPlane ? tolerance / dot(plane, dvec3(toLight)) : tolerance;
  if (!(float(tnear) < tfar)) {  // nothing can lie between: lit
    decided(pixel);
    return 0.0;
  }
  samples[kSampleVec4s * pixel] = vec4(vec3(origin), float(tnear));
#if IZB_POSITIONAL
  samples[kSampleVec4s * pixel + 1u] = vec4(toLight, tfar);
#endif
  vec2 g;
  float w;
  bool onGrid = izbGridPos(P.xyz, g, w);
  // Light views listed one after another (several), or one: a point off its grid is listed at
  // its border.
  if (IZB_SEVERAL_VIEWS != 0) {
    // Outside this view's window: another view lists it, or none and it keeps its fallback bit.
    if (!onGrid || any(lessThan(g, vec2(0.0))) || any(greaterThanEqual(g, vec2(float(u_izbGrid))))) return 0.0;
    decided(pixel);
  } else if (!onGrid) {
    // Behind a perspective light: the reference would trace it, the grid cannot list it.
    atomicOr(fallbackBits[pixel >> 5], 1u << (pixel & 31u));
    return 0.0;
  }
  ivec2 cell = izbCell(g);
  uint index = uint(cell.y * u_izbGrid + cell.x);
  pixelCell[pixel] = uvec2(index, own);
  pixelRank[pixel] = atomicAdd(counts[index], 1u);
  // The cell's farthest sample, for the triangles pass to skip casters beyond it. Read first: a
  // cell's samples are neighbours on screen and mostly agree, and a read costs less than an atomic.
  uint away = orderedBits(izbAwayKey(u_izbViewProj * vec4(vec3(origin), 1.0)));
  uint state = kCellWords * index;
  if (away > cellState[state]) atomicMax(cellState[state], away);
  // The cell's one owner triangle, which the triangles pass need not walk it for (a triangle
  // never shadows its own samples): the first sample claims it, any other marks it mixed.
  uint tag = own < uint(u_izbTriangles) ? own + 1u : kMixedOwners;
  uint seen = cellState[state + 2u];
  if (seen != tag && seen != kMixedOwners) {
    uint before = atomicCompSwap(cellState[state + 2u], 0u, tag);
    if (before != 0u && before != tag) atomicMax(cellState[state + 2u], kMixedOwners);
  }
  return w;  // > 0: izbGridPos held
}

// The listed samples' w range. How many were listed is the prefix sum's total
// (izb_scan.comp): an atomic per sample on that one address cost llvmpipe 6 ms at 1280x720.
void main() {
  float w = listSample();
#if IZB_W_RANGE  // the grid's w varies (a warp under a sun): the triangles pass culls by it
  if (!(w > 0.0)) return;
  // Tested before the atomic: the range settles within the first groups, and a plain read
  // costs llvmpipe far less than an atomic maximum on one address (a stale read only adds one).
  uint low = ~floatBitsToUint(w), high = floatBitsToUint(w);
  if (low > counters[3]) atomicMax(counters[3], low);
  if (high > counters[4]) atomicMax(counters[4], high);
#endif
}
