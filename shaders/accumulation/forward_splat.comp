// Forward shadow mapping (Zhang 1998): every light-view sample (texel of view 0) sent forward
// into the eye view, lighting the eye pixels of its splat that show the same surface.
//
// One invocation per light texel: its world position rebuilt from the depth the shadow pass
// stored (light-view linear depth over [near, far]), projected into the eye view, and the
// rectangle of pixels its splat covers there (pixel centres inside it) tested one by one. A
// compute scatter rather than GL points: no rasterizer setup of 4 M point primitives a frame,
// and a splat whose centre is off screen still lights the pixels it covers on screen. Every
// write is the same "lit", so invocations need no atomics. Splats of more than kInlinePixels
// go to a list the rasterizer draws (accumulation/forward_large.glsl).
//
// Splat sizes, the test and the shared declarations: accumulation/forward_splat.glsl.
#include "accumulation/forward_splat.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, ivec2(u_mapSize)))) return;
  float d = texelFetch(u_shadowMap, ivec3(t, 0), 0).r;
  if (!(d < 1.0)) return;  // empty texel: nothing was rasterized there, nothing to send
  vec3 sampleAt;
  vec2 window;
  if (!sampleLands(t, d, sampleAt, window)) return;
  vec2 half_ = splatHalfSides(t, d, window);
  // Pixels whose centres lie in [window - half, window + half), the splat's rectangle, on screen
  // (clamped as floats: a sample far off screen must not overflow the integer conversion).
  ivec2 lo = ivec2(clamp(ceil(window - half_ - 0.5), vec2(0.0), u_screenSize));
  ivec2 hi = ivec2(clamp(ceil(window + half_ - 0.5) - 1.0, vec2(-1.0), u_screenSize - 1.0));
  if (any(greaterThan(lo, hi))) return;
  ivec2 size = hi - lo + 1;
  vec2 texel = vec2(t) + 0.5;
  if (size.x * size.y > kInlinePixels) {
    uint i = atomicAdd(forwardLargeCount, 1u);
    if (i < uint(u_largeCapacity)) {
      forwardLarge[i] = ForwardLarge(uvec4(packPair(t), packPair(lo), packPair(hi), 0u), vec4(sampleAt, 1.0));
      return;
    }
  }
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) lightIfSameSurface(ivec2(x, y), sampleAt, texel);
}
