// Final colour of a scene of several lights: Scene::light with the technique's visibility (as
// passes/shade.frag) plus the other lights' direct terms summed by passes/light_direct.frag.
#define SL_DEFERRED
#include "common/shading.glsl"

uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform sampler2D u_visibility;
uniform sampler2D u_otherDirect;
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
  float vis = texelFetch(u_visibility, pixel, 0).r;
  vec3 others = texelFetch(u_otherDirect, pixel, 0).rgb;
  if (isnan(vis) || isinf(vis) || any(isnan(others)) || any(isinf(others))) {
    o_color = kNonFinite;
    return;
  }
  o_color = shadeDirect(texelFetch(u_gAlbedo, pixel, 0).rgb, directLight(P.xyz, N, vis) + others);
}
