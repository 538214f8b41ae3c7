// Shadow-map texels projected into the camera image as a checkerboard: large squares mean
// one texel covers many pixels (undersampling); texels smaller than a pixel blend to one tone.
#include "common/light.glsl"
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform sampler2D u_gAlbedo;
out vec4 o_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) { o_color = vec4(0.1, 0.1, 0.12, 1.0); return; }
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  ShadowCoord c = layoutShadowCoord(P.xyz);
  vec4 sc = vec4(c.uv, c.depth, c.view >= 0 ? 1.0 : 0.0);
  float shade = 0.35 + 0.65 * max(dot(N, directionToLight(P.xyz)), 0.0);
  if (sc.w == 0.0 || any(lessThan(sc.xy, vec2(0.0))) || any(greaterThan(sc.xy, vec2(1.0)))) {
    o_color = vec4(vec3(0.3) * shade, 1.0);
    return;
  }
  // Filtered at the screen's sampling rate: the checkerboard is box-filtered over the pixel's
  // footprint in texels (fwidth), so texels smaller than a pixel average to a flat tone instead of
  // moire; texel borders are drawn as lines only where a texel spans several pixels.
  vec2 p = sc.xy * u_shadowMapSize;
  vec2 w = max(fwidth(p), vec2(1e-4));
  vec2 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;
  float checker = 0.5 - 0.5 * i.x * i.y;
  vec3 a = vec3(0.95, 0.75, 0.3), b = vec3(0.25, 0.35, 0.75);
  vec3 color = mix(a, b, checker);
  float pixelsPerTexel = 1.0 / max(max(w.x, w.y), 1e-4);
  vec2 border = min(fract(p), 1.0 - fract(p)) / w;  // distance to the nearest texel edge, in pixels
  float line = (1.0 - smoothstep(0.0, 1.0, min(border.x, border.y))) * smoothstep(4.0, 8.0, pixelsPerTexel);
  color = mix(color, vec3(0.08), 0.7 * line);
  o_color = vec4(pow(color * shade, vec3(1.0 / 2.2)), 1.0);
}
