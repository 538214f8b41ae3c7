// Forward shading for techniques with no accumulation: the shadow test and the shading happen
// while the scene is rasterized, with no G-buffer round trip (what keeps a software rasterizer
// interactive). Needs the technique prelude (layout + representation modules).
#include "common/surface.glsl"
#include "common/visibility_term.glsl"
#include "common/shading.glsl"

layout(location = 0) out vec4 o_color;
layout(location = 1) out vec2 o_visibility;  // visibility, confidence (eq. 5 of Scherzer et al.)

void main() {
  vec3 F = surfaceFacetNormal();
  materialAlphaTest(v_uv);
  vec3 N = surfaceNormal();
  o_visibility = visibilityTerm(v_world, N, F);
  o_color = shadeSurface(materialColor(v_uv).rgb, v_world, N, o_visibility.x);
}
