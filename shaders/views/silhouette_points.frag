// The silhouette map over the depth map (layer 0, letterboxed like the shadow-map view): dark
// grey depth, texels that hold a silhouette point in orange, and when a texel spans several
// pixels the point itself as a red dot.
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
  vec2 size = vec2(textureSize(u_shadowMap, 0).xy);
  float d = texture(u_shadowMap, vec3(uv, 0.0)).r;
  vec3 color = vec3(d >= 1.0 ? 0.0 : pow(1.0 - d, 1.5) * 0.5 + 0.05);
  vec2 s = uv * size - 0.5;
  ivec2 c = ivec2(floor(s));
  if (all(greaterThanEqual(c, ivec2(0))) && all(lessThan(c, ivec2(size)))) {
    vec2 p = texelFetch(u_silhouetteMap, ivec3(c, 0), 0).rg;
    if (p.x >= 0.0) {
      color = mix(color, vec3(1.0, 0.55, 0.1), 0.7);
      float pixelsPerTexel = side / size.x;
      if (length((s - vec2(c) - p) * pixelsPerTexel) < max(1.5, 0.12 * pixelsPerTexel)) color = vec3(1.0, 0.1, 0.1);
    }
  }
  o_color = vec4(color, 1.0);
}
