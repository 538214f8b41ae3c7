// Final colour from a visibility computed earlier (by an accumulation or the visibility pass).
#define SL_DEFERRED
#include "common/shading.glsl"

uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform sampler2D u_visibility;
in vec2 v_uv;
out vec4 o_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) {
    o_color = vec4(skyColor(v_uv.y), 1.0);
    return;
  }
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  o_color = shadePixel(pixel, P.xyz, N, texelFetch(u_visibility, pixel, 0).r);
}
