// One more light of a scene of several (Scene::otherLights): its direct term in its colour,
// added (blending ONE, ONE) into the viewport's sum of the other lights (RGBA16F), which
// passes/shade_lights.frag reads.
// The light is this program's (common/light.glsl with its defines), so every light is shaded by
// the same formula as a scene's only light.
#include "common/shading.glsl"

uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
#ifdef SL_SHADOWED_LIGHT
uniform sampler2D u_visibility;  // what the technique computed for this light
#endif
out vec4 o_direct;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) {
    o_direct = vec4(0.0);
    return;
  }
#ifdef SL_SHADOWED_LIGHT
  float vis = texelFetch(u_visibility, pixel, 0).r;
  // A non-finite visibility stays non-finite in the sum: the shade pass shows it as magenta.
  if (isnan(vis) || isinf(vis)) {
    o_direct = vec4(vis);
    return;
  }
#else
  float vis = 1.0;
#endif
  o_direct = vec4(directLight(P.xyz, normalize(texelFetch(u_gNormal, pixel, 0).xyz), vis), 0.0);
}
