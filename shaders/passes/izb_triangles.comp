// Irregular z-buffer, pass 4: one invocation per caster triangle. It walks the grid cells of
// its light-space bounds (widened by a hundredth of a cell against the rounding of the
// projection: the test below is exact, the cells only have to hold every candidate) and tests
// each listed sample against the triangle itself: the ray from the sample's start toward the
// light hits the triangle between the height tolerance and the light (Moller-Trumbore, as a ray
// tracer would), and an alpha-masked triangle only where its texture at the hit is opaque
// (nearest texel, repeat: the reference's filter). A hit sets the sample's bit (atomicOr).
layout(local_size_x = 64) in;
#include "passes/izb_common.glsl"
uniform int u_izbTriangles;

float alphaAt(Material m, Triangle t, float u, float v) {
  float alpha = m.alpha.y;
  int w = int(m.texture.y), h = int(m.texture.z);
  if (w <= 0 || h <= 0) return alpha;
  vec2 uv = (1.0 - u - v) * t.uv01.xy + u * t.uv01.zw + v * t.uv2.xy;
  int x = int(floor(uv.x * float(w))) % w, y = int(floor(uv.y * float(h))) % h;
  x += x < 0 ? w : 0;
  y += y < 0 ? h : 0;
  uint byteIndex = m.texture.x + uint(y * w + x);
  uint word = alphaBytes[byteIndex >> 2];
  return alpha * float((word >> (8u * (byteIndex & 3u))) & 255u) / 255.0;
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

void main() {
  uint id = gl_GlobalInvocationID.x;
  if (id >= uint(u_izbTriangles)) return;
  Triangle t = triangles[id];
  Material m = materials[floatBitsToUint(t.c.w)];
  // A masked material with no texture is all base alpha: below the cutoff it casts nothing.
  bool masked = m.texture.w != 0u;
  if (masked && m.texture.y == 0u && m.alpha.y < m.alpha.x) return;
  vec2 g0, g1, g2;
  ivec2 lo = ivec2(0), hi = ivec2(u_izbGrid - 1);
  // Behind a perspective light's plane the projection wraps around: walk the whole grid.
  if (izbGridPos(t.a.xyz, g0) && izbGridPos(t.b.xyz, g1) && izbGridPos(t.c.xyz, g2)) {
    vec2 mn = min(g0, min(g1, g2)) - 0.01, mx = max(g0, max(g1, g2)) + 0.01;
    lo = izbCell(mn);
    hi = izbCell(mx);
  }
  vec3 a = t.a.xyz, e1 = t.b.xyz - a, e2 = t.c.xyz - a;
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      uint cell = uint(y * u_izbGrid + x);
      uint begin = offsets[cell], end = min(offsets[cell + 1u], uint(u_izbCapacity));
      for (uint k = begin; k < end; ++k) {
        uint pixel = list[k];
        uint bit = 1u << (pixel & 31u);
        if ((shadowBits[pixel >> 5] & bit) != 0u) continue;  // already occluded
        Sample s = samples[pixel];
        if (s.triangle == id) continue;  // its own triangle never shadows it
        float u, v;
        if (!hits(s, a, e1, e2, u, v)) continue;
        if (masked && alphaAt(m, t, u, v) < m.alpha.x) continue;
        atomicOr(shadowBits[pixel >> 5], bit);
      }
    }
  }
}
