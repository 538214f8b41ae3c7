#include "common/surface.glsl"

layout(location = 0) out vec4 o_position;  // w = 1: covered
#ifndef SL_GBUFFER_POSITION_ONLY  // the renderer turns the other draw buffers off then
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_albedo;
// Which triangle this is (instance + 1, triangle index in the mesh: 0 = none) and its packed
// facet normal: the reference traces from that exact triangle, deferred passes test the facet.
layout(location = 3) out uvec4 o_surface;
#ifdef SL_WRITE_MOTION
layout(location = 4) out vec4 o_motion;    // previous frame NDC, w = 1 when valid
#endif
#endif

uniform int u_instanceId;

void main() {
#ifdef SL_GBUFFER_POSITION_ONLY
  materialAlphaTest(v_uv);
  o_position = vec4(v_world, 1.0);
#else
  vec3 facet = surfaceFacetNormal();
  materialAlphaTest(v_uv);
  vec3 n = surfaceNormal();  // two-sided leaves and open meshes shade their visible side
  o_position = vec4(v_world, 1.0);
  o_normal = vec4(n, 0.0);
  o_albedo = vec4(materialColor(v_uv).rgb, 1.0);
  o_surface = uvec4(uint(u_instanceId + 1), uint(gl_PrimitiveID), packFacet(facet), 0u);
#ifdef SL_WRITE_MOTION
  o_motion = v_prevClip.w > 1e-6 ? vec4(v_prevClip.xyz / v_prevClip.w, 1.0) : vec4(0.0);
#endif
#endif
}
