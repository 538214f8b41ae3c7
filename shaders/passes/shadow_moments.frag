// Shadow pass of the soft pre-filtered representations (vssm, convolution-soft): the nearest
// caster's depth (the depth attachment keeps the nearest) turned into the representation's
// moments, one output per moment target. The others draw depth alone and take the moments in
// their filter pass (MomentMapState::momentsInShadowPass says why). The representation module (technique prelude) defines representationMoments.
#include "common/material.glsl"
in vec3 v_world;
in vec2 v_uv;
layout(location = 0) out vec4 o_moments0;
#if SL_MOMENT_TARGETS > 1
layout(location = 1) out vec4 o_moments1;
#endif
#if SL_MOMENT_TARGETS > 2
layout(location = 2) out vec4 o_moments2;
#endif
#if SL_MOMENT_TARGETS > 3
layout(location = 3) out vec4 o_moments3;
#endif
#if SL_MOMENT_TARGETS > 4
layout(location = 4) out vec4 o_moments4;
#endif
#if SL_MOMENT_TARGETS > 5
layout(location = 5) out vec4 o_moments5;
#endif
#if SL_MOMENT_TARGETS > 6
layout(location = 6) out vec4 o_moments6;
#endif
#if SL_MOMENT_TARGETS > 7
layout(location = 7) out vec4 o_moments7;
#endif

#include "passes/caster_fragment.glsl"

void main() {
  CasterFragment caster = casterFragment(v_world, v_uv);
  if (!caster.covered) discard;
  materialAlphaTest(caster.uv);
#ifdef SL_LAYOUT_CULLS_CASTER_FRAGMENTS
  if (layoutCullsCasterFragment(v_world)) discard;  // e.g. behind a paraboloid's hemisphere
#endif
#ifdef SL_PERSPECTIVE_MAP
  float z = caster.depth;
  gl_FragDepth = clamp(z, 0.0, 1.0);
#else
  float z = gl_FragCoord.z;
#endif
  vec4 m[SL_MOMENT_TARGETS];
  representationMoments(sanitizeDepth(z), m);
  o_moments0 = m[0];
#if SL_MOMENT_TARGETS > 1
  o_moments1 = m[1];
#endif
#if SL_MOMENT_TARGETS > 2
  o_moments2 = m[2];
#endif
#if SL_MOMENT_TARGETS > 3
  o_moments3 = m[3];
#endif
#if SL_MOMENT_TARGETS > 4
  o_moments4 = m[4];
#endif
#if SL_MOMENT_TARGETS > 5
  o_moments5 = m[5];
#endif
#if SL_MOMENT_TARGETS > 6
  o_moments6 = m[6];
#endif
#if SL_MOMENT_TARGETS > 7
  o_moments7 = m[7];
#endif
}
