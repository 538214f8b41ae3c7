// A pixel of a large forward splat (accumulation/forward_splat_quad.vert): lit when it shows the
// sample's surface (accumulation/forward_splat.glsl), else left as the texel pass left it.
#include "accumulation/forward_scatter.glsl"
flat in float v_sampleDepth;
flat in vec2 v_texel;
out vec2 o_visibility;

void main() {
  if (!lightsPixel(ivec2(gl_FragCoord.xy), v_sampleDepth, v_texel)) discard;
  o_visibility = vec2(1.0, 1.0);
}
