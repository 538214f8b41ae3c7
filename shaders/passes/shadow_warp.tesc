// Caster patches of a warped shadow map (LogPSM: layouts/logpsm.glsl): each edge is split finely
// enough that its chords stay within u_logpsm_max_error texels of the warped curve. Along t (the
// map's y before the warp, 0 at its near side) u = ln(1 + t/δ)/C bends by |u''| = 1/(C (δ + t)²),
// and n equal pieces of an edge from t_a to t_b err by (t_b - t_a)² / (8 n² C (δ + t_a)²) at most.
layout(vertices = 3) out;
in vec3 v_world[];
in vec2 v_uv[];
out vec3 tc_world[];
out vec2 tc_uv[];
uniform float u_logpsm_max_error;
uniform float u_logpsm_tessellate;  // 0: no subdivision (what a plain rasterizer would draw)

float edgeT(int i) { return (lightViewProjMatrix[u_shadowView] * vec4(v_world[i], 1.0)).y * 0.5 + 0.5; }

float edgeLevel(float ta, float tb, float delta, float c) {
  float lo = clamp(min(ta, tb), 0.0, 1.0), hi = clamp(max(ta, tb), 0.0, 1.0);
  if (!(delta > 0.0) || hi <= lo || u_logpsm_tessellate < 0.5) return 1.0;  // straight: no warp, off the map
  float errorU = u_logpsm_max_error / u_shadowMapSize;
  float pieces = (hi - lo) / ((delta + lo) * sqrt(8.0 * c * errorU));
  return clamp(ceil(pieces), 1.0, 64.0);
}

void main() {
  tc_world[gl_InvocationID] = v_world[gl_InvocationID];
  tc_uv[gl_InvocationID] = v_uv[gl_InvocationID];
  if (gl_InvocationID == 0) {
    float delta = lightViewSplit[u_shadowView].w;
    float c = delta > 0.0 ? logWarpLog1p(1.0 / delta) : 1.0;
    float t0 = edgeT(0), t1 = edgeT(1), t2 = edgeT(2);
    // Outer level i is the edge opposite vertex i.
    gl_TessLevelOuter[0] = edgeLevel(t1, t2, delta, c);
    gl_TessLevelOuter[1] = edgeLevel(t2, t0, delta, c);
    gl_TessLevelOuter[2] = edgeLevel(t0, t1, delta, c);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
  }
}
