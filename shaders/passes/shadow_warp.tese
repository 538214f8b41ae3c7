// Caster patches of a warped shadow map (see shadow_warp.tesc): every generated vertex is placed
// on the flat triangle, then warped by the layout (layoutClip), so the rasterized chords follow
// the bent image of the triangle.
layout(triangles, equal_spacing, ccw) in;
in vec3 tc_world[];
in vec2 tc_uv[];
out vec3 v_world;
out vec2 v_uv;
#ifdef SL_LOG_WARP
// The patch's constants for exact caster fragments (passes/warp_caster.glsl; shadow_warp.tesc).
#include "passes/warp_caster_outputs.glsl"
patch in float tc_exactCaster;
patch in vec3 tc_weightRows[3];
patch in vec3 tc_cornerDepth;
patch in vec3 tc_leastWeights;
patch in vec4 tc_warpTerms;
#endif

void main() {
  vec3 b = gl_TessCoord;
  v_world = b.x * tc_world[0] + b.y * tc_world[1] + b.z * tc_world[2];
  v_uv = b.x * tc_uv[0] + b.y * tc_uv[1] + b.z * tc_uv[2];
  gl_Position = layoutClip(v_world);
#ifdef SL_LOG_WARP
  v_cornerUv0 = tc_uv[0], v_cornerUv1 = tc_uv[1], v_cornerUv2 = tc_uv[2];
  v_weightRow0 = tc_weightRows[0], v_weightRow1 = tc_weightRows[1], v_weightRow2 = tc_weightRows[2];
  v_cornerDepth = tc_cornerDepth;
  v_leastWeights = tc_leastWeights;
  v_warpTerms = tc_warpTerms;
  v_mapNdc = gl_Position.xy / gl_Position.w;
  v_exactCaster = tc_exactCaster;
#endif
}
