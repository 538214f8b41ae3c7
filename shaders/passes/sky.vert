// A full-screen triangle on the far plane: drawn after the scene with depth test LEQUAL, so
// only background pixels run the sky shader.
out vec2 v_uv;
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  v_uv = p;
  gl_Position = vec4(p * 2.0 - 1.0, 1.0, 1.0);
}
