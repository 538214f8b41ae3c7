// Caster patches of a warped shadow map (LogPSM: layouts/logpsm.glsl): each edge is split finely
// enough that its chords stay within u_logpsm_max_error texels of the warped curve. Along t (the
// map's y before the warp, 0 at its near side) u = ln(1 + t/δ)/C bends by |u''| = 1/(C (δ + t)²),
// and n equal pieces of an edge from t_a to t_b err by (t_b - t_a)² / (8 n² C (δ + t_a)²) at most.
// With the perspective part (logpsm.perspective) x' = X/W bends along an edge as well: with W
// and X linear in the edge parameter s, x'' = -2 dW (dX W - X dW) / W^3, whose numerator is the
// same all along the edge, so |x''| is largest at the smaller W, and n pieces err by that / (8 n^2).
// In front of the pole x' is monotonic along an edge (its derivative is (dX W - X dW) / W^2): an
// edge with both ends beyond one side of the map stays off it and needs no pieces for x.
layout(vertices = 3) out;
in vec3 v_world[];
in vec2 v_uv[];
out vec3 tc_world[];
out vec2 tc_uv[];
uniform float u_logpsm_max_error;
uniform float u_logpsm_tessellate;  // 0: no subdivision (what a plain rasterizer would draw)

vec4 patchClip(int i) { return lightViewProjMatrix[u_shadowView] * vec4(v_world[i], 1.0); }

float edgeLevel(vec4 a, vec4 b, float delta, float c) {
  float ta = a.y * 0.5 + 0.5, tb = b.y * 0.5 + 0.5;  // y is linear before the warp (layouts/logpsm.glsl)
  float lo = clamp(min(ta, tb), 0.0, 1.0), hi = clamp(max(ta, tb), 0.0, 1.0);
  if (!(delta > 0.0) || hi <= lo || u_logpsm_tessellate < 0.5) return 1.0;  // straight: no warp, off the map
  float errorU = u_logpsm_max_error / u_shadowMapSize;
  float pieces = (hi - lo) / ((delta + lo) * sqrt(8.0 * c * errorU));
  float dW = b.w - a.w, wMin = max(min(a.w, b.w), 1e-3);
  float xa = a.x / max(a.w, 1e-3), xb = b.x / max(b.w, 1e-3);
  bool offSide = a.w > 0.0 && b.w > 0.0 && ((xa > 1.0 && xb > 1.0) || (xa < -1.0 && xb < -1.0));
  float curveX = offSide ? 0.0 : 2.0 * abs(dW) * abs((b.x - a.x) * a.w - a.x * dW) / (wMin * wMin * wMin);
  pieces = max(pieces, sqrt(curveX * u_shadowMapSize / (16.0 * u_logpsm_max_error)));  // 0 when W = 1
  return clamp(ceil(pieces), 1.0, 64.0);
}

void main() {
  tc_world[gl_InvocationID] = v_world[gl_InvocationID];
  tc_uv[gl_InvocationID] = v_uv[gl_InvocationID];
  if (gl_InvocationID == 0) {
    float delta = lightViewSplit[u_shadowView].w;
    float c = delta > 0.0 ? logWarpLog1p(1.0 / delta) : 1.0;
    vec4 c0 = patchClip(0), c1 = patchClip(1), c2 = patchClip(2);
    // Outer level i is the edge opposite vertex i.
    gl_TessLevelOuter[0] = edgeLevel(c1, c2, delta, c);
    gl_TessLevelOuter[1] = edgeLevel(c2, c0, delta, c);
    gl_TessLevelOuter[2] = edgeLevel(c0, c1, delta, c);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
  }
}
