// Caster patches of a warped shadow map (see shadow_warp.tesc): every generated vertex is placed
// on the flat triangle, then warped by the layout (layoutClip), so the rasterized chords follow
// the bent image of the triangle.
layout(triangles, equal_spacing, ccw) in;
in vec3 tc_world[];
in vec2 tc_uv[];
out vec3 v_world;
out vec2 v_uv;

void main() {
  vec3 b = gl_TessCoord;
  v_world = b.x * tc_world[0] + b.y * tc_world[1] + b.z * tc_world[2];
  v_uv = b.x * tc_uv[0] + b.y * tc_uv[1] + b.z * tc_uv[2];
  gl_Position = layoutClip(v_world);
}
