// Sample-distribution bounds (Lauritzen, Salvi, Lefohn 2011): min/max over the visible pixels of
// their camera view depth and of their position in the light's fixed basis, reduced per work
// group in shared memory, then once per group into the result buffer. Floats are stored as
// order-preserving uints so that atomicMin/atomicMax compare them correctly.
// Each invocation reduces a 4x4 block of pixels in registers first, so a group of 16x16 covers
// 64x64 pixels and the shared atomics run once per invocation, not once per pixel (on a CPU
// rasterizer the atomics, serialized per lane, were most of the pass).
// SL_BOUNDS_FROM_DEPTH: the pixels read from a depth target (the shaded frame's, for a later
// frame's fit) instead of the G-buffer's world positions; depth 1 is uncovered. The point is
// then the pixel's clip-space position and u_cameraView and u_lightView come premultiplied by
// the inverse of the camera's view-projection (sdsm.cpp), so the world position is never formed.
layout(local_size_x = 16, local_size_y = 16) in;
uniform mat4 u_cameraView;
uniform mat4 u_lightView;
#ifdef SL_BOUNDS_FROM_DEPTH
uniform sampler2D u_depth;
#define SL_BOUNDS_SOURCE u_depth
// xyz: the point, w: 1 where covered.
vec4 surfaceAt(ivec2 pixel) {
  float z = texelFetch(u_depth, pixel, 0).r;
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(textureSize(u_depth, 0)) * 2.0 - 1.0;
  return vec4(ndc, z * 2.0 - 1.0, z < 1.0 ? 1.0 : 0.0);
}
#else
uniform sampler2D u_gPosition;
#define SL_BOUNDS_SOURCE u_gPosition
vec4 surfaceAt(ivec2 pixel) { return texelFetch(u_gPosition, pixel, 0); }
#endif
layout(std430) buffer DepthBounds {
  uint bounds[8];  // view depth min, max; light x min, max; y min, max; light depth min, max
};
shared uint groupBounds[8];
const int kBlock = 4;  // pixels per invocation along each axis (sdsm.cpp dispatches by it)

#include "common/ordered_bits.glsl"

void main() {
  if (gl_LocalInvocationIndex < 8u) groupBounds[gl_LocalInvocationIndex] = (gl_LocalInvocationIndex & 1u) == 0u ? 0xffffffffu : 0u;
  barrier();
  ivec2 size = textureSize(SL_BOUNDS_SOURCE, 0);
  vec4 lo = vec4(1.0 / 0.0), hi = vec4(-1.0 / 0.0);
  bool found = false;
  for (int j = 0; j < kBlock; ++j)
    for (int i = 0; i < kBlock; ++i) {
      ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) * kBlock + ivec2(i, j);
      if (any(greaterThanEqual(pixel, size))) continue;
      vec4 P = surfaceAt(pixel);
      // Covered and finite: a NaN would poison the bounds for the frames that read them.
      if (!(P.w > 0.5) || any(isnan(P.xyz)) || any(isinf(P.xyz))) continue;
      vec4 q = u_lightView * vec4(P.xyz, 1.0);
      vec2 c = (u_cameraView * vec4(P.xyz, 1.0)).zw;
      q.xyz /= q.w;  // w = 1 from world positions
      vec4 v = vec4(-c.x / c.y, q.x, q.y, -q.z);
      lo = min(lo, v);
      hi = max(hi, v);
      found = true;
    }
  if (found) {
    for (int k = 0; k < 4; ++k) {
      atomicMin(groupBounds[2 * k], orderedBits(lo[k]));
      atomicMax(groupBounds[2 * k + 1], orderedBits(hi[k]));
    }
  }
  barrier();
  if (gl_LocalInvocationIndex < 8u) {
    uint i = gl_LocalInvocationIndex;
    if ((i & 1u) == 0u)
      atomicMin(bounds[i], groupBounds[i]);
    else
      atomicMax(bounds[i], groupBounds[i]);
  }
}
