// Forward against backward: white where a splat lit the pixel, dark grey where both say shadow,
// magenta where the backward nearest test says lit but no splat reached the pixel (a hole),
// cyan where a splat lit a pixel the backward test shadows (light spread across an edge).
uniform sampler2D u_forward;
uniform sampler2D u_backward;
uniform sampler2D u_gPosition;
in vec2 v_uv;
out vec4 o_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (texelFetch(u_gPosition, pixel, 0).w < 0.5) {
    o_color = vec4(0.1, 0.1, 0.15, 1.0);
    return;
  }
  bool fwd = texelFetch(u_forward, pixel, 0).r > 0.5;
  bool bwd = texelFetch(u_backward, pixel, 0).r > 0.5;
  vec3 c = fwd ? (bwd ? vec3(0.9) : vec3(0.1, 0.9, 0.9)) : (bwd ? vec3(1.0, 0.1, 0.9) : vec3(0.2));
  o_color = vec4(c, 1.0);
}
