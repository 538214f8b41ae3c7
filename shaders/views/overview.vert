// Scene seen from an overview camera, for the light-space view.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
uniform mat4 u_model;
uniform mat4 u_viewProj;
out vec3 v_normal;
out vec2 v_uv;
void main() {
  v_normal = transpose(inverse(mat3(u_model))) * a_normal;
  v_uv = a_uv;
  gl_Position = u_viewProj * u_model * vec4(a_position, 1.0);
}
