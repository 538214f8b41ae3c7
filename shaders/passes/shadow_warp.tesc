// Caster patches of a warped shadow map (LogPSM: layouts/logpsm.glsl): each edge is split finely
// enough that its chords stay within u_logpsm_max_error texels of the warped curve. Along t (the
// map's y before the warp, 0 at its near side) u = ln(1 + t/δ)/C bends by |u''| = 1/(C (δ + t)²),
// and n equal pieces of an edge from t_a to t_b err by (t_b - t_a)² / (8 n² C (δ + t_a)²) at most.
// With the perspective part (logpsm.perspective) x' = X/W is projective along an edge as well:
// with W and X linear in the edge parameter s, |x''| = 2 |W'| |X' - x' W'| / W^2, at most
// 2 |dW| (|dX| + |dW|) / W_min^2 on the map (|x'| <= 1), and n pieces err by that / (8 n^2).
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
  float dW = abs(b.w - a.w), wMin = max(min(a.w, b.w), 1e-3);
  float curveX = 2.0 * dW * (abs(b.x - a.x) + dW) / (wMin * wMin);  // 0 for the orthographic x (W = 1)
  pieces = max(pieces, sqrt(curveX * u_shadowMapSize / (16.0 * u_logpsm_max_error)));
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
