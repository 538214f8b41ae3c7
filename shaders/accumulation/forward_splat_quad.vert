// A large splat of forward shadow mapping as a rectangle of pixels (gl_InstanceID: its entry in
// accumulation/forward_large.glsl): the pixels whose centres lie in [first, last + 1), so the
// rasterizer covers exactly the pixels the texel pass would have looped over.
#include "accumulation/forward_large.glsl"
uniform vec2 u_screenSize;
flat out float v_sampleDepth;
flat out vec2 v_texel;

void main() {
  ForwardLarge splat = forwardLarge[gl_InstanceID];
  vec2 lo = vec2(unpackPair(splat.where.y)), hi = vec2(unpackPair(splat.where.z)) + 1.0;
  const ivec2 corner[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));
  vec2 pixel = mix(lo, hi, vec2(corner[gl_VertexID]));
  gl_Position = vec4(pixel / u_screenSize * 2.0 - 1.0, 0.0, 1.0);
  v_sampleDepth = uintBitsToFloat(splat.where.w);
  v_texel = vec2(unpackPair(splat.where.x)) + 0.5;
}
