// Shadow-map rasterization; the layout module (from the technique prelude) supplies layoutClip.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_model;
out vec3 v_world;
out vec2 v_uv;
#include "passes/caster_depth.glsl"
#ifdef SL_CASTER_DEPTH_VARYING
out float v_casterDepth;  // the layout's stored depth (passes/caster_depth.glsl)
#endif
#ifdef SL_LOG_WARP
#include "passes/warp_caster_outputs.glsl"
#endif

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  v_uv = a_uv;
  gl_Position = layoutClip(world.xyz);
#ifdef SL_CASTER_DEPTH_VARYING
  v_casterDepth = layoutDepth(world.xyz);
#endif
#ifdef SL_LOG_WARP
  warpCasterNotSolved();  // read only where no tessellation stage follows (warp_caster.glsl)
#endif
#ifdef SL_PACKED_VIEWS
  // Views packed into one layer: each draws only its own triangle of it (the renderer enables
  // the two clip distances for such a shadow pass).
  vec2 sides = packedTriangleSides(lightViewOwnClip(gl_Position), u_shadowView);
  gl_ClipDistance[0] = sides.x;
  gl_ClipDistance[1] = sides.y;
#endif
}
