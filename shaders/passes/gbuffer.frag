#include "common/material.glsl"

in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_prevClip;

layout(location = 0) out vec4 o_position;  // w = 1: covered
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_albedo;
#ifdef SL_WRITE_MOTION
layout(location = 3) out vec4 o_motion;    // previous frame NDC, w = 1 when valid
#endif

void main() {
  materialAlphaTest(v_uv);
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;  // two-sided leaves and open meshes shade their visible side
  o_position = vec4(v_world, 1.0);
  o_normal = vec4(n, 0.0);
  o_albedo = vec4(materialColor(v_uv).rgb, 1.0);
#ifdef SL_WRITE_MOTION
  o_motion = v_prevClip.w > 1e-6 ? vec4(v_prevClip.xyz / v_prevClip.w, 1.0) : vec4(0.0);
#endif
}
