#include "common/material.glsl"
uniform vec3 u_lightDirection;
in vec3 v_normal;
in vec2 v_uv;
out vec4 o_color;
void main() {
  materialAlphaTest(v_uv);
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  float l = 0.35 + 0.65 * max(dot(n, -normalize(u_lightDirection)), 0.0);
  o_color = vec4(pow(materialColor(v_uv).rgb * l * 0.8, vec3(1.0 / 2.2)), 1.0);
}
