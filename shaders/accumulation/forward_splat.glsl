// Forward shadow mapping's splat (Zhang 1998), shared by the texel pass
// (accumulation/forward_splat.comp) and the rasterized large splats
// (accumulation/forward_splat_quad.frag): where a light texel's sample lands in the eye view,
// how large its splat is, and whether it lights a pixel. Needs the technique prelude with
// SL_DEFERRED (the G-buffer's facet) and SL_REPRESENTATION_IN_COMPUTE (the representation:
// u_shadowMap, its filter radius in the bias).
#include "common/light.glsl"
#include "common/bias.glsl"
#include "common/facet.glsl"
#include "common/light_ray.glsl"
layout(rg16f, binding = 0) uniform writeonly image2D u_visibilityOut;
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
uniform mat4 u_eyeViewProj;
uniform int u_mapSize;
uniform vec2 u_screenSize;
uniform float u_forward_splat;
uniform float u_forward_footprint;
uniform float u_forward_grow;  // off: Zhang's fixed forward.splat

const float kMaxSplat = 255.0;  // pixels: beyond it a texel spans so much of the view that holes are the method's

// The world position of the sample of texel t (texel units) with stored depth d, in view 0.
vec3 sampleWorld(vec2 texel, float d) { return lightRayPoint(texel / float(u_mapSize), d, 0); }

// The window offset, in pixels, from the sample to where a neighbour one texel along `step`
// lands (its own stored depth, or this one's where it is empty); behind the eye: as far as
// allowed.
vec2 offsetTo(ivec2 t, ivec2 step, float d, vec2 here) {
  ivec2 n = clamp(t + step, ivec2(0), ivec2(u_mapSize - 1));
  float dn = texelFetch(u_shadowMap, ivec3(n, 0), 0).r;
  vec4 c = u_eyeViewProj * vec4(sampleWorld(vec2(t + step) + 0.5, dn < 1.0 ? dn : d), 1.0);
  if (c.w <= 1e-6) return vec2(kMaxSplat);
  return c.xy / c.w * 0.5 * u_screenSize - here;
}

// The splat's half sides in pixels for the sample of texel t at window position `window`.
// Zhang's fixed square (forward.splat), or with forward.grow the bounding box of the texel's
// footprint: the pixels whose surface falls within forward.footprint / 2 texels of the sample
// lie in the parallelogram spanned by that fraction of the steps to the neighbours' landings,
// whose half-extent along x is the sum of the two steps' |x| (a square of the longest step
// misses its corners where the texel grid runs diagonally across the screen). At least half a
// pixel, at most kMaxSplat / 2.
vec2 splatHalfSides(ivec2 t, float d, vec2 window) {
  if (u_forward_grow < 0.5) return vec2(0.5 * u_forward_splat);
  vec2 here = window - 0.5 * u_screenSize;  // the centred window position offsetTo measures from
  vec2 alongU = max(abs(offsetTo(t, ivec2(1, 0), d, here)), abs(offsetTo(t, ivec2(-1, 0), d, here)));
  vec2 alongV = max(abs(offsetTo(t, ivec2(0, 1), d, here)), abs(offsetTo(t, ivec2(0, -1), d, here)));
  vec2 half_ = 0.5 * (alongU + alongV) * u_forward_footprint + 0.5;
  return clamp(mix(half_, vec2(0.5 * kMaxSplat), isnan(half_)), vec2(0.5), vec2(0.5 * kMaxSplat));
}

// Whether a map position falls in the sample's texel (forward.footprint texels wide).
bool inSampleTexel(ShadowCoord sc, vec2 texel) {
  return sc.view >= 0 && all(lessThanEqual(abs(sc.uv * float(u_mapSize) - texel), vec2(0.5 * u_forward_footprint)));
}

// Zhang compares the sample with the eye's depth buffer; here the pixel's surface point
// (G-buffer) is taken to the light view, where "the same surface" is exact on slopes too: the
// point falls in the sample's texel and is not behind the stored depth beyond the technique's
// bias, the test a backward map makes. Facing away: unlit.
bool lightsPixel(ivec2 pixel, vec3 sampleAt, vec2 texel) {
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) return false;
#ifndef SL_BIAS_MODE_IS_NORMAL_OFFSET
  // Without a normal offset the test reads the map at the surface point itself: the texel test,
  // which rejects most pixels of a large splat, runs before the normals are fetched.
  ShadowCoord sc = layoutShadowCoordIn(P.xyz, 0);
  if (!inSampleTexel(sc, texel)) return false;
#endif
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  vec3 F = gbufferFacetNormal(pixel, N);
  vec3 L = directionToLight(P.xyz);
  float cosTheta = dot(N, L);
  if (!surfaceFacesLight(P.xyz, N, F, L)) return false;
#ifdef SL_BIAS_MODE_IS_NORMAL_OFFSET
  ShadowCoord sc = layoutShadowCoordIn(biasReceiverPosition(P.xyz, N, cosTheta, 0), 0);
  if (!inSampleTexel(sc, texel)) return false;
#endif
  return sc.depth - biasDepth(P.xyz, cosTheta, 0) <= layoutDepthIn(sampleAt, 0);
}

#include "accumulation/forward_large.glsl"
const int kInlinePixels = 64;  // splats of at most this many pixels are tested in the texel pass

// The sample of texel t with stored depth d: its world position, and false when it lands
// nowhere (behind the eye; non-finite).
bool sampleLands(ivec2 t, float d, out vec3 sampleAt, out vec2 window) {
  sampleAt = sampleWorld(vec2(t) + 0.5, d);
  vec4 clip = u_eyeViewProj * vec4(sampleAt, 1.0);
  // The splat is clipped to the screen, not culled with its centre as GL culls a point: a
  // texel stretched over hundreds of pixels can have its sample off screen while its splat
  // still covers the view (beyond Zhang; low-sun 11.5 % -> 1.6 % wrong at 160x90).
  window = vec2(0.0);
  if (!(clip.w > 1e-6)) return false;  // behind the eye: it lands nowhere
  window = (clip.xy / clip.w * 0.5 + 0.5) * u_screenSize;
  return !any(isnan(window)) && !any(isinf(window));
}

void lightIfSameSurface(ivec2 pixel, vec3 sampleAt, vec2 texel) {
  if (lightsPixel(pixel, sampleAt, texel)) imageStore(u_visibilityOut, pixel, vec4(1.0, 1.0, 0.0, 0.0));
}
