#include "common/material.glsl"
in vec3 v_world;
in vec2 v_uv;

#include "passes/caster_fragment.glsl"

void main() {
  CasterFragment caster = casterFragment(v_world, v_uv);
  if (!caster.covered) discard;
  materialAlphaTest(caster.uv);
#ifdef SL_LAYOUT_CULLS_CASTER_FRAGMENTS
  if (layoutCullsCasterFragment(v_world)) discard;  // e.g. behind a paraboloid's hemisphere
#endif
#ifdef SL_PERSPECTIVE_MAP
  // Perspective maps store light-view linear depth like orthographic ones do, so biases mean
  // the same everywhere. (Orthographic depth is already linear: no per-fragment write, which
  // keeps the shadow pass cheap on a software rasterizer.)
  gl_FragDepth = clamp(caster.depth, 0.0, 1.0);
#endif
}
