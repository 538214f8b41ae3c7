// Caster patches of a warped shadow map (LogPSM: layouts/logpsm.glsl): each edge is split into
// pieces whose chords stay within u_logpsm_max_error texels of the warped curve
// (passes/warp_levels.glsl says how many). Where the sorting pass runs
// (logpsm.sort_casters), only triangles with an edge of more than one piece come here.
layout(vertices = 3) out;
in vec3 v_world[];
in vec2 v_uv[];
out vec3 tc_world[];
out vec2 tc_uv[];
#include "passes/warp_levels.glsl"
// Per patch, for exact caster fragments (passes/warp_caster.glsl): the barycentric weights as a
// function of the view's clip X and Y (both affine over the triangle's plane), the corners'
// depths, the least weights a kept fragment may have, and W's dependence on Y with the log's C.
patch out float tc_exactCaster;
patch out vec3 tc_weightRows[3];
patch out vec3 tc_cornerDepth;
patch out vec3 tc_leastWeights;
patch out vec4 tc_warpTerms;

vec4 patchClip(int i) { return lightViewProjMatrix[u_shadowView] * vec4(v_world[i], 1.0); }

// clip: the corners' patchClip; slack: how far (world) outside the triangle a fragment may lie
// and still be kept.
void casterConstants(vec4 clip[3], vec3 n, float slack, float delta, float c) {
  vec4 r1 = warpMatrixRow(1), r3 = warpMatrixRow(3);
  mat3 corners;  // columns (X, Y, 1) of each corner: (X, Y, 1) = corners * weights
  for (int i = 0; i < 3; ++i) {
    corners[i] = vec3(clip[i].xy, 1.0);
    tc_cornerDepth[i] = layoutDepth(v_world[i]);
    float edge = length(v_world[(i + 2) % 3] - v_world[(i + 1) % 3]);
    tc_leastWeights[i] = -max(slack * edge / length(n), 1e-5);  // weight i times corner i's height
  }
  mat3 weights = inverse(corners);
  tc_weightRows[0] = vec3(weights[0][0], weights[1][0], weights[2][0]);
  tc_weightRows[1] = vec3(weights[0][1], weights[1][1], weights[2][1]);
  tc_weightRows[2] = vec3(weights[0][2], weights[1][2], weights[2][2]);
  // W depends on the light view's y alone (layouts/logpsm.glsl): W = a Y + b (0 and 1 without
  // the perspective part).
  float a = dot(r3.xyz, r1.xyz) / dot(r1.xyz, r1.xyz);
  tc_warpTerms = vec4(a, r3.w - a * r1.w, c, delta);
}

void main() {
  tc_world[gl_InvocationID] = v_world[gl_InvocationID];
  tc_uv[gl_InvocationID] = v_uv[gl_InvocationID];
  if (gl_InvocationID == 0) {
    vec2 warp = warpDeltaAndC();
    float delta = warp.x, c = warp.y;
    vec4 c0 = patchClip(0), c1 = patchClip(1), c2 = patchClip(2);
    vec3 levels = warpEdgeLevels(c0, c1, c2, warp);  // outer level i is the edge opposite vertex i
    gl_TessLevelOuter[0] = levels.x;
    gl_TessLevelOuter[1] = levels.y;
    gl_TessLevelOuter[2] = levels.z;
    if (levels.x == 0.0) {  // wholly beyond one side of the map: not drawn
      gl_TessLevelInner[0] = 0.0;
      return;
    }
    // A patch with a fine edge would get as fine an interior: pieces squared (64 pieces: about
    // 6000 triangles). Its fragments instead take depth and coverage from the triangle itself
    // (passes/warp_caster.glsl), which needs no interior pieces, only a small solve per fragment.
    // A caster seen nearly edge on keeps the fine interior and interpolated values.
    float finest = max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
    vec3 n = cross(v_world[1] - v_world[0], v_world[2] - v_world[0]);
    vec3 middle = (v_world[0] + v_world[1] + v_world[2]) / 3.0;
    vec4 centre = layoutClip(middle), rowX, rowY;
    warpRayRows(centre.xy / centre.w, rowX, rowY);
    vec3 ray = cross(rowX.xyz, rowY.xyz);
    bool edgeOn = !(abs(dot(n, ray)) > kWarpEdgeOnCos * length(n) * length(ray));
    bool exact = finest > 1.0 && !edgeOn;
    tc_exactCaster = exact ? 1.0 : 0.0;
    vec4 clip[3] = vec4[3](c0, c1, c2);
    if (exact) casterConstants(clip, n, (u_logpsm_max_error + 1.0) * layoutTexelWorldSize(middle, u_shadowView), delta, c);
    gl_TessLevelInner[0] = exact ? 1.0 : finest;
  }
}
