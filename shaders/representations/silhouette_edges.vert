// Silhouette edges (world-space segments) into the light view the pass draws (u_shadowView).
layout(location = 0) in vec3 a_position;
out vec4 v_clip;
out float v_depth;

void main() {
  v_clip = layoutClip(a_position);
  v_depth = layoutDepth(a_position);
  gl_Position = v_clip;
}
