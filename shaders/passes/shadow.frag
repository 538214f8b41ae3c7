#include "common/material.glsl"
in vec3 v_world;
in vec2 v_uv;

void main() {
  materialAlphaTest(v_uv);
#ifdef SL_LOG_WARP
  if (layoutBehindPole(v_world)) discard;
#endif
#ifdef SL_LAYOUT_CULLS_CASTER_FRAGMENTS
  if (layoutCullsCasterFragment(v_world)) discard;  // e.g. behind a paraboloid's hemisphere
#endif
#ifdef SL_PERSPECTIVE_MAP
  // Perspective maps store light-view linear depth like orthographic ones do, so biases mean
  // the same everywhere. (Orthographic depth is already linear: no per-fragment write, which
  // keeps the shadow pass cheap on a software rasterizer.)
  gl_FragDepth = clamp(layoutDepth(v_world), 0.0, 1.0);
#endif
}
