// The visible pixels' bounds in each view of a point light (techniques/point/visible_fit.cpp;
// sample-distribution fitting, Lauritzen et al. 2011, applied per face: beyond the papers). A pixel
// counts in the view whose axis is nearest its direction from the light (the largest distance
// along the view's axis: the face the lookup reads; for the paraboloids, the hemisphere on its
// side of the plane through the light). Per view: min/max of its image coordinates (a face's
// tangent coordinates x/-z, y/-z; a paraboloid's whole-disk image, app/part/light_space.h
// paraboloidDiskImage) and of its distance (-z; the paraboloid's radial distance). Points
// beyond the light's range are unlit whatever the map says and are left out. Each invocation
// reduces 16x16 pixels in registers, then writes each view it saw with global atomics on floats
// stored as order-preserving uints (depth_bounds.comp). Measured on llvmpipe at 640x360: about
// 6 ms, of which 1.5 ms is the dispatch, the read-back and the refit; 4x4 pixels per invocation
// with shared atomics per group of 16x16 took 8 ms, and indexing the registers by constants
// only changed nothing.
layout(local_size_x = 8, local_size_y = 8) in;
const int kMaxViews = 6;
const int kBlock = 16;
uniform sampler2D u_gPosition;
uniform int u_viewCount;
uniform bool u_paraboloid;
uniform vec3 u_lightPos;
uniform float u_lightRange;
uniform mat4 u_faceView[kMaxViews];
layout(std430) buffer PointFaceBounds {
  uint bounds[kMaxViews * 6];  // per view: x min, max; y min, max; distance min, max
};

#include "common/ordered_bits.glsl"
#include "layouts/paraboloid_image.glsl"

// The view a point reads, and its image coordinates and distance there (xy, z).
int viewOf(vec3 P, out vec3 image) {
  int best = 0;
  vec3 v = (u_faceView[0] * vec4(P, 1.0)).xyz;
  for (int f = 1; f < u_viewCount; ++f) {
    vec3 w = (u_faceView[f] * vec4(P, 1.0)).xyz;
    if (-w.z > -v.z) {
      best = f;
      v = w;
    }
  }
  if (u_paraboloid) {
    float r = length(v);
    vec3 d = v / max(r, 1e-30);
    image = vec3(paraboloidDiskImage(d), r);
  } else {
    image = vec3(v.xy / max(-v.z, 1e-30), -v.z);
  }
  return best;
}

void main() {
  ivec2 size = textureSize(u_gPosition, 0);
  vec3 lo[kMaxViews], hi[kMaxViews];
  for (int f = 0; f < kMaxViews; ++f) {
    lo[f] = vec3(1.0 / 0.0);
    hi[f] = vec3(-1.0 / 0.0);
  }
  for (int j = 0; j < kBlock; ++j)
    for (int k = 0; k < kBlock; ++k) {
      ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) * kBlock + ivec2(k, j);
      if (any(greaterThanEqual(pixel, size))) continue;
      vec4 P = texelFetch(u_gPosition, pixel, 0);
      if (!(P.w > 0.5) || any(isnan(P.xyz)) || any(isinf(P.xyz))) continue;
      if (length(P.xyz - u_lightPos) > u_lightRange) continue;
      vec3 image;
      int f = viewOf(P.xyz, image);
      if (any(isnan(image)) || any(isinf(image))) continue;  // the light's own position
      lo[f] = min(lo[f], image);
      hi[f] = max(hi[f], image);
    }
  for (int f = 0; f < u_viewCount; ++f) {
    if (!(lo[f].x <= hi[f].x)) continue;
    for (int c = 0; c < 3; ++c) {
      atomicMin(bounds[f * 6 + 2 * c], orderedBits(lo[f][c]));
      atomicMax(bounds[f * 6 + 2 * c + 1], orderedBits(hi[f][c]));
    }
  }
}
