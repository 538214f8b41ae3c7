layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;

uniform mat4 u_model;
uniform mat4 u_prevModel;      // the instance's transform last frame (moving objects)
uniform mat4 u_viewProj;
uniform mat4 u_prevViewProj;
uniform mat4 u_prevView;

out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
out vec4 v_prevClip;
out float v_prevViewDepth;  // linear depth in the previous frame's view (reprojection checks)

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  v_normal = transpose(inverse(mat3(u_model))) * a_normal;
  v_uv = a_uv;
  vec4 prevWorld = u_prevModel * vec4(a_position, 1.0);
  v_prevClip = u_prevViewProj * prevWorld;
  v_prevViewDepth = -(u_prevView * prevWorld).z;
  gl_Position = u_viewProj * world;
}
