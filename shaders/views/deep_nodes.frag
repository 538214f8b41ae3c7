// The deep shadow map as the light sees it (view 0, over the whole map: outside the window the
// deep map covers (deep_fit.h) it is black, no function): nodes used per texel, 0 black, then the
// ramp up to SL_DEEP_NODES (yellow); texels whose function was empty stay black. The key along
// the bottom has one band per node count, 0 at the left. Needs the technique prelude.
uniform vec2 u_viewSize;
in vec2 v_uv;
out vec4 o_color;

vec3 deepRamp(float t) {
  t = clamp(t, 0.0, 1.0);
  vec3 a = vec3(0.15, 0.1, 0.4), b = vec3(0.1, 0.5, 0.55), c = vec3(0.35, 0.75, 0.35), d = vec3(0.98, 0.9, 0.2);
  return t < 0.333 ? mix(a, b, t * 3.0) : t < 0.667 ? mix(b, c, t * 3.0 - 1.0) : mix(c, d, t * 3.0 - 2.0);
}

vec3 countColor(float n) { return n < 0.5 ? vec3(0.0) : deepRamp((n - 1.0) / max(float(SL_DEEP_NODES) - 1.0, 1.0)); }

void main() {
  float keyHeight = 0.06;
  if (v_uv.y < keyHeight) {
    float n = floor(v_uv.x * float(SL_DEEP_NODES + 1));
    // a dark notch between bands
    float edge = fract(v_uv.x * float(SL_DEEP_NODES + 1));
    o_color = vec4(edge < 0.04 ? vec3(0.5) : countColor(n), 1.0);
    return;
  }
  vec2 uv = vec2(v_uv.x, (v_uv.y - keyHeight) / (1.0 - keyHeight));
  uv = (uv - u_deepWindow[0].xy) / u_deepWindow[0].zw;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) {
    o_color = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  ivec2 size = textureSize(u_deepCounts, 0).xy;
  float n = texelFetch(u_deepCounts, ivec3(clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1), 0), 0).r;
  o_color = vec4(countColor(n), 1.0);
}
