// LogPSM (techniques/layouts/logpsm.h): one orthographic view whose y, the view direction as the
// light sees it, is warped logarithmically; δ per view in lightViewSplit[view].w. Casters are
// tessellated (passes/shadow_warp.tesc/.tese) so their bent edges are drawn as short chords.
#define SL_LOG_WARP

// ln(1 + x) without the cancellation of log(1.0 + x) for tiny x (weak warps: large δ).
float logWarpLog1p(float x) { return abs(x) < 1e-3 ? x * (1.0 - x * (0.5 - x / 3.0)) : log(1.0 + x); }

// t in [0, 1] from the map's near side -> u = ln(1 + t/δ) / ln(1 + 1/δ); δ <= 0: no warp. Points
// before the near side are extended up to just short of the pole at t = -δ (they are off the map).
float logWarp(float t, float delta) {
  if (!(delta > 0.0)) return t;
  return logWarpLog1p(max(t / delta, -0.999)) / logWarpLog1p(1.0 / delta);
}

// δ (e^x - 1) without the cancellation of exp(x) - 1 for tiny x: the inverse warp's t for
// x = u ln(1 + 1/δ) (callers that know ln(1 + 1/δ) already pass it multiplied in).
float logWarpExpm1(float x, float delta) { return delta * (abs(x) < 1e-3 ? x * (1.0 + x * (0.5 + x / 6.0)) : exp(x) - 1.0); }

// The inverse: the t whose warp is u (u = 0 at the map's near side, 1 at its far side).
float logWarpInverse(float u, float delta) {
  if (!(delta > 0.0)) return u;
  return logWarpExpm1(u * logWarpLog1p(1.0 / delta), delta);
}

#include "layouts/single_matrix.glsl"

// A fragment's light ray in the view the shadow pass draws: the points p with rowX.(p, 1) = 0
// and rowY.(p, 1) = 0 land on its map position ndc (x' = X / W; y through the log warp's t,
// which W does not divide; δ <= 0, a spot's fallback: y' = Y / W). Their cross product is the
// ray's direction. Used to tell casters seen edge on (passes/shadow_warp.tesc).
// Row i of the drawn view's matrix: clip coordinate i of p is dot(row, (p, 1)).
vec4 warpMatrixRow(int i) {
  mat4 m = lightViewProjMatrix[u_shadowView];
  return vec4(m[0][i], m[1][i], m[2][i], m[3][i]);
}

void warpRayRows(vec2 ndc, out vec4 rowX, out vec4 rowY) {
  vec4 r0 = warpMatrixRow(0), r1 = warpMatrixRow(1), r3 = warpMatrixRow(3);
  rowX = r0 - ndc.x * r3;
  float delta = lightViewSplit[u_shadowView].w;
  rowY = delta > 0.0 ? r1 - vec4(0.0, 0.0, 0.0, 2.0 * logWarpInverse(ndc.y * 0.5 + 0.5, delta) - 1.0)
                     : r1 - ndc.y * r3;
}

// Below this |cos| between a caster's plane normal and its rays the triangle is nearly edge on
// to the light, and its barycentric weights as functions of clip X and Y ill-conditioned.
const float kWarpEdgeOnCos = 0.1;
