// The flat (facet) normal of the rasterized triangle and its packing in the G-buffer's surface
// target. A smooth normal can face the light where the triangle itself does not (the shadow
// terminator); the reference traces from the triangle, so techniques test the same facet
// (docs/reference.md, "Conventions that decide pixels").

// Facet normal from screen derivatives of the world position, turned to the side of the shading
// normal N (the side the camera sees). Call it before any discard: derivatives are undefined
// after one. Fragment stages only (screen derivatives).
#ifdef SL_FRAGMENT
vec3 facetNormalFromDerivatives(vec3 worldPos, vec3 N) {
  vec3 f = cross(dFdx(worldPos), dFdy(worldPos));
  float len = length(f);
  if (!(len > 0.0) || isinf(len)) return N;  // degenerate footprint: fall back to N
  f /= len;
  return dot(f, N) < 0.0 ? -f : f;
}
#endif

// Octahedral mapping of a unit vector to [-1,1]^2 (one snorm16 pair: about 5e-5 rad).
vec2 facetOctEncode(vec3 n) {
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  vec2 e = n.xy;
  if (n.z < 0.0) e = (1.0 - abs(e.yx)) * vec2(e.x >= 0.0 ? 1.0 : -1.0, e.y >= 0.0 ? 1.0 : -1.0);
  return e;
}

vec3 facetOctDecode(vec2 e) {
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  return normalize(n);
}

uint packFacet(vec3 n) { return packSnorm2x16(facetOctEncode(n)); }
vec3 unpackFacet(uint bits) { return facetOctDecode(unpackSnorm2x16(bits)); }

#ifdef SL_DEFERRED
// The facet normal the G-buffer stored for this pixel (passes/gbuffer.frag), on N's side.
uniform usampler2D u_gSurface;
vec3 gbufferFacetNormal(ivec2 pixel, vec3 N) {
  uvec4 s = texelFetch(u_gSurface, pixel, 0);
  if (s.x == 0u) return N;
  vec3 f = unpackFacet(s.z);
  return dot(f, N) < 0.0 ? -f : f;
}
#endif
