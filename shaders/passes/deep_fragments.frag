// Deep shadow map, step 1 (Lokovic & Veach 2000): every semi-transparent fragment the light sees
// goes into its texel's list as (light depth, sample + alpha). The light image is supersampled
// (section 4.1): with a multisampled framebuffer the shader runs once per covered sample
// (gl_SampleID), and the sample's index rides in the integer part of the second value (alpha is
// in (0, 1], so sample s holds s + alpha in (s, s + 1]). Lists have a fixed length
// (SL_DEEP_FRAGMENTS); a fragment that finds its list full is counted, never written past the
// end, so memory stays bounded and the status reports it. Needs the technique prelude.
#include "common/material.glsl"
uniform float u_deep_size;
layout(std430) buffer DeepCounts { uint deepCount[]; };
layout(std430) writeonly buffer DeepFragments { vec2 deepFragment[]; };
layout(std430) buffer DeepOverflow { uint deepOverflow[3]; };  // dropped, relaxed, samples
in vec3 v_world;
in vec2 v_uv;

#include "passes/caster_fragment.glsl"

void main() {
  CasterFragment caster = casterFragment(v_world, v_uv);
  if (!caster.covered) return;
  vec2 uv = caster.uv;
  float alpha = clamp(materialColor(uv).a, 0.0, 1.0);
  if (!(alpha > 0.0)) return;  // fully clear (or NaN): no attenuation
#ifdef SL_LAYOUT_CULLS_CASTER_FRAGMENTS
  if (layoutCullsCasterFragment(v_world)) return;  // e.g. behind a paraboloid's hemisphere
#endif
  atomicMax(deepOverflow[2], uint(gl_NumSamples));  // the divisor of the compress pass
  int size = int(u_deep_size + 0.5);
  ivec2 texel = ivec2(gl_FragCoord.xy);
  uint index = uint((u_shadowView * size + texel.y) * size + texel.x);
  uint slot = atomicAdd(deepCount[index], 1u);
  if (slot < uint(SL_DEEP_FRAGMENTS))
    deepFragment[index * uint(SL_DEEP_FRAGMENTS) + slot] = vec2(clamp(caster.depth, 0.0, 1.0), float(gl_SampleID) + alpha);
  else
    atomicAdd(deepOverflow[0], 1u);
}
