// Forward shadow mapping (Zhang 1998), as Zhang runs it (forward.scatter): every light-view
// sample (texel of view 0) sent forward into the eye view, lighting the eye pixels of its splat
// that show the same surface.
//
// One invocation per light texel: its sample (the depth the shadow pass stored, light-view
// linear depth over [near, far], on the texel's ray) projected into the eye view, and the
// rectangle of pixels its splat covers there (pixel centres inside it) tested one by one against
// the receivers pass's records. A compute scatter rather than GL points: no rasterizer setup of
// 4 M point primitives a frame, and a splat whose centre is off screen still lights the pixels
// it covers on screen. Every write is the same "lit", so invocations need no atomics. Splats of
// more than kInlinePixels go to a list the rasterizer draws (accumulation/forward_large.glsl).
//
// Splat sizes, the test and the shared declarations: accumulation/forward_splat.glsl; the
// same lit pixels found per eye pixel instead (the default): accumulation/forward_gather.comp.
#include "accumulation/forward_scatter.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, ivec2(u_mapSize)))) return;
  float d;
  ivec2 lo, hi;
  if (!splatOfTexel(t, d, lo, hi)) return;
  ivec2 size = hi - lo + 1;
  vec2 texel = vec2(t) + 0.5;
  if (size.x * size.y > kInlinePixels) {
    uint i = atomicAdd(forwardLargeCount, 1u);
    if (i < uint(u_largeCapacity)) {
      forwardLarge[i] = ForwardLarge(uvec4(packPair(t), packPair(lo), packPair(hi), floatBitsToUint(d)));
      return;
    }
  }
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x)
      if (lightsPixel(ivec2(x, y), d, texel)) markLit(ivec2(x, y));
}
