// What a warped map's caster fragments read (passes/warp_caster.glsl): written per patch by the
// evaluation stage (passes/shadow_warp.tese), and as "not solved" (v_exactCaster = 0) by the
// vertex stage where a view of the layout draws without tessellation (a spot's fallback).
flat out float v_exactCaster;
flat out vec3 v_weightRow0;
flat out vec3 v_weightRow1;
flat out vec3 v_weightRow2;
flat out vec3 v_cornerDepth;
flat out vec3 v_leastWeights;
flat out vec4 v_warpTerms;
flat out vec2 v_cornerUv0;
flat out vec2 v_cornerUv1;
flat out vec2 v_cornerUv2;
noperspective out vec2 v_mapNdc;

void warpCasterNotSolved() {
  v_exactCaster = 0.0;
  v_weightRow0 = v_weightRow1 = v_weightRow2 = v_cornerDepth = v_leastWeights = vec3(0.0);
  v_warpTerms = vec4(0.0);
  v_cornerUv0 = v_cornerUv1 = v_cornerUv2 = v_mapNdc = vec2(0.0);
}
