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

#include "layouts/single_matrix.glsl"
