// How finely a caster triangle's edges are cut for a warped map (LogPSM: layouts/logpsm.glsl),
// shared by the control stage (passes/shadow_warp.tesc) and the pass that sorts the triangles
// which need no pieces out of the tessellated draw (passes/warp_classify.comp), so both decide
// alike.
// Each edge is split finely enough that its chords stay within u_logpsm_max_error texels of the
// warped curve. Along t (the map's y before the warp, 0 at its near side) u = ln(1 + t/δ)/C bends
// by |u''| = 1/(C (δ + t)²), and n equal pieces of an edge from t_a to t_b err by (t_b - t_a)² / (8
// n² C (δ + t_a)²) at most. With the perspective part (logpsm.perspective) x' = X/W bends along an
// edge as well: with W and X linear in the edge parameter s, x'' = -2 dW (dX W - X dW) / W^3, whose
// numerator is the same all along the edge, so |x''| is largest at the smaller W, and n pieces err
// by that / (8 n^2). In front of the pole x' is monotonic along an edge (its derivative is (dX W -
// X dW) / W^2): an edge with both ends beyond one side of the map stays off it and needs no pieces
// for x. Nor does one with both ends before or beyond the map in t: the warp keeps t's order, so
// its chords stay off the map as well. A patch wholly beyond one side is not drawn at all (outer
// levels 0): on a software tessellator (llvmpipe) every patch drawn costs, whatever its levels.
uniform float u_logpsm_max_error;
uniform float u_logpsm_tessellate;  // 0: no subdivision (what a plain rasterizer would draw)

// Pieces for the edge a-b so that those which reach the map, t >= tLow along it, err within the
// budget: along t (u'' in the edge parameter is (t_b - t_a)² u''(t)) and across (x'' above, W
// affine in t with the perspective part, constant without).
float piecesFrom(vec4 a, vec4 b, float tLow, float delta, float c) {
  float ta = a.y * 0.5 + 0.5, tb = b.y * 0.5 + 0.5, dW = b.w - a.w;
  float pieces = abs(tb - ta) / ((delta + tLow) * sqrt(8.0 * c * u_logpsm_max_error / u_shadowMapSize));
  float xa = a.x / max(a.w, 1e-3), xb = b.x / max(b.w, 1e-3);
  bool offSide = a.w > 0.0 && b.w > 0.0 && ((xa > 1.0 && xb > 1.0) || (xa < -1.0 && xb < -1.0));
  if (offSide || dW == 0.0) return pieces;
  float wLow = tb == ta ? min(a.w, b.w) : a.w + (tLow - ta) / (tb - ta) * dW;
  wLow = max(wLow, 1e-3);
  float curveX = 2.0 * abs(dW) * abs((b.x - a.x) * a.w - a.x * dW) / (wLow * wLow * wLow);
  return max(pieces, sqrt(curveX * u_shadowMapSize / (16.0 * u_logpsm_max_error)));
}

// The pieces are equal over the whole edge, and only those that reach the map need to follow the
// curve: the one that crosses the map's near side (t = 0, where the warp bends most) starts up to
// one piece before it. A first count from the map's part alone says how far that is; the count
// for pieces from there is at least as large, so its pieces are no longer and start no earlier.
float edgeLevel(vec4 a, vec4 b, float delta, float c) {
  float ta = a.y * 0.5 + 0.5, tb = b.y * 0.5 + 0.5;  // y is linear before the warp (layouts/logpsm.glsl)
  bool offMapT = max(ta, tb) < 0.0 || min(ta, tb) > 1.0;
  if (!(delta > 0.0) || offMapT || u_logpsm_tessellate < 0.5) return 1.0;  // straight: no warp, off the map
  float lo = clamp(min(ta, tb), 0.0, 1.0);
  float first = max(piecesFrom(a, b, lo, delta, c), 1.0);
  float tLow = max(max(lo - abs(tb - ta) / first, min(ta, tb)), -0.999 * delta);
  return clamp(ceil(piecesFrom(a, b, tLow, delta, c)), 1.0, 64.0);
}

// All three corners beyond one side of the map: in t (linear along y before the warp, which keeps
// its order) or in x' = X/W where W > 0 at every corner (X > W is then a half-space in front of
// the pole, and the triangle lies in it).
bool patchOffMap(vec4 a, vec4 b, vec4 c) {
  vec3 t = vec3(a.y, b.y, c.y) * 0.5 + 0.5;
  if (max(t.x, max(t.y, t.z)) < 0.0 || min(t.x, min(t.y, t.z)) > 1.0) return true;
  if (min(a.w, min(b.w, c.w)) <= 0.0) return false;
  vec3 x = vec3(a.x, b.x, c.x) / vec3(a.w, b.w, c.w);
  return max(x.x, max(x.y, x.z)) < -1.0 || min(x.x, min(x.y, x.z)) > 1.0;
}

// View u_shadowView's log warp: δ (0: none) and C = ln(1 + 1/δ) (1 without a warp).
vec2 warpDeltaAndC() {
  float delta = lightViewSplit[u_shadowView].w;
  return vec2(delta, delta > 0.0 ? logWarpLog1p(1.0 / delta) : 1.0);
}

// The outer levels of the triangle with these corners' clip positions in view u_shadowView
// (warp: warpDeltaAndC()), level i for the edge opposite corner i; (0, 0, 0) when it lies wholly
// beyond one side of the map (not drawn).
vec3 warpEdgeLevels(vec4 c0, vec4 c1, vec4 c2, vec2 warp) {
  if (patchOffMap(c0, c1, c2)) return vec3(0.0);
  float delta = warp.x, c = warp.y;
  return vec3(edgeLevel(c1, c2, delta, c), edgeLevel(c2, c0, delta, c), edgeLevel(c0, c1, delta, c));
}
