// The shadow map as the light sees it, letterboxed into the view, near = bright.
uniform sampler2D u_shadowMap;
uniform vec2 u_viewSize;
in vec2 v_uv;
out vec4 o_color;

void main() {
  float side = min(u_viewSize.x, u_viewSize.y);
  vec2 uv = (gl_FragCoord.xy - 0.5 * (u_viewSize - vec2(side))) / side;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) {
    o_color = vec4(0.08, 0.08, 0.1, 1.0);
    return;
  }
  float d = texture(u_shadowMap, uv).r;
  o_color = vec4(vec3(d >= 1.0 ? 0.0 : pow(1.0 - d, 1.5) * 0.9 + 0.1), 1.0);
}
