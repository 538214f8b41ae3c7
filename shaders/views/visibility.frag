// The shadow term alone: white = lit, black = shadowed, magenta = NaN/Inf.
uniform sampler2D u_visibility;
uniform sampler2D u_gPosition;
out vec4 o_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (texelFetch(u_gPosition, pixel, 0).w < 0.5) { o_color = vec4(0.2, 0.2, 0.25, 1.0); return; }
  float v = texelFetch(u_visibility, pixel, 0).r;
  o_color = (isnan(v) || isinf(v)) ? vec4(1.0, 0.0, 1.0, 1.0) : vec4(vec3(clamp(v, 0.0, 1.0)), 1.0);
}
