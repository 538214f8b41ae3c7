// The rasterized surface point as every forward pass sees it (from passes/gbuffer.vert).
#include "common/material.glsl"
#include "common/facet.glsl"

in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_prevClip;
in float v_prevViewDepth;

// Normal facing the camera: two-sided leaves and open meshes shade their visible side, exactly
// as the G-buffer stores them (the reference traces from that).
vec3 surfaceNormal() {
  vec3 n = normalize(v_normal);
  return gl_FrontFacing ? n : -n;
}

// The triangle's own normal on the side of surfaceNormal(); call before materialAlphaTest.
vec3 surfaceFacetNormal() { return facetNormalFromDerivatives(v_world, surfaceNormal()); }
