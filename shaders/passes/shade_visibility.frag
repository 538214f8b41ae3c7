// Visibility and colour in one pass, for techniques with no accumulation: one G-buffer read
// and one full-screen pass fewer, which matters on a software rasterizer.
#include "common/visibility_term.glsl"
#include "common/shading.glsl"

uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
in vec2 v_uv;
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec2 o_visibility;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) {
    o_color = vec4(skyColor(v_uv.y), 1.0);
    o_visibility = vec2(1.0, 0.0);
    return;
  }
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  o_visibility = visibilityTerm(P.xyz, N);
  o_color = shadePixel(pixel, P.xyz, N, o_visibility.x);
}
