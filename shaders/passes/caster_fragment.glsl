// What the shadow passes' fragment stages know of the caster at a fragment: its stored depth
// (layoutDepth), its texture coordinate, and whether the fragment is the caster's at all. A
// warped map's fragments solve them exactly (passes/warp_caster.glsl); others interpolate.
struct CasterFragment {
  float depth;
  vec2 uv;
  bool covered;  // false: not the caster's (a warped map: outside the triangle, behind the pole)
};

#ifdef SL_LOG_WARP
#include "passes/warp_caster.glsl"
#endif
#include "passes/caster_depth.glsl"
#ifdef SL_CASTER_DEPTH_VARYING
in float v_casterDepth;
#endif

CasterFragment casterFragment(vec3 interpolatedWorld, vec2 interpolatedUv) {
#ifdef SL_LOG_WARP
  return warpCasterFragment(interpolatedWorld, interpolatedUv);
#elif defined(SL_CASTER_DEPTH_VARYING)
  return CasterFragment(v_casterDepth, interpolatedUv, true);
#else
  return CasterFragment(layoutDepth(interpolatedWorld), interpolatedUv, true);
#endif
}
