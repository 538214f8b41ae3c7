// Which split of a partitioned layout each pixel reads (colour per view), and the blend bands
// where a second split is mixed in (the two colours mixed, hatched). Single-view layouts are one
// colour.
#include "common/light.glsl"
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
out vec4 o_color;

vec3 viewColour(int i) {
  const vec3 palette[8] = vec3[8](vec3(0.90, 0.30, 0.25), vec3(0.95, 0.75, 0.20), vec3(0.35, 0.75, 0.30),
                                  vec3(0.25, 0.55, 0.90), vec3(0.65, 0.40, 0.85), vec3(0.30, 0.80, 0.80),
                                  vec3(0.90, 0.55, 0.70), vec3(0.60, 0.60, 0.60));
  return palette[clamp(i, 0, 7)];
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) {
    o_color = vec4(0.1, 0.1, 0.12, 1.0);
    return;
  }
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  float shade = 0.45 + 0.55 * max(dot(N, directionToLight(P.xyz)), 0.0);
  ShadowCoord c = layoutShadowCoord(P.xyz);
  vec3 colour = c.view < 0 ? vec3(0.3) : viewColour(c.view);
  if (c.view2 >= 0 && c.weight2 > 0.0) {
    colour = mix(colour, viewColour(c.view2), c.weight2);
    // Hatching marks the band itself, also where two neighbouring colours are alike.
    if (mod(gl_FragCoord.x + gl_FragCoord.y, 8.0) < 2.0) colour *= 0.55;
  }
  o_color = vec4(pow(colour * shade, vec3(1.0 / 2.2)), 1.0);
}
