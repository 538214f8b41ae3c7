// Forward shadow mapping's splat (Zhang 1998), shared by the gather
// (accumulation/forward_gather.comp, the default) and the scatter (accumulation/forward_splat.comp
// and its rasterized large splats, accumulation/forward_scatter.glsl): where a light texel's
// sample lands in the eye view, how large its splat is, and whether it lights a pixel. Needs the
// technique prelude with SL_DEFERRED (the G-buffer's facet) and SL_REPRESENTATION_IN_COMPUTE (the
// representation: u_shadowMap, its filter radius in the bias).
#include "common/light.glsl"
#include "common/bias.glsl"
#include "common/facet.glsl"
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

// Where samples land: the eye's clip position of the sample of a texel (texel units) with
// stored depth d in view 0, through matrices taken once a frame (mapToClip) instead of through
// the world position, whose two inverses and four matrix products each of the five samples a
// splat needs (its own and its neighbours') paid. rayFromMap takes (texel, 0, 1) to the
// texel's ray in the light view (homogeneous), clipFromLightView a light-view point to the eye's
// clip space. In an orthographic view the clip position is affine in (texel, d): a neighbour's
// is the sample's plus a column per texel and per unit of depth.
struct MapToClip {
  mat4 rayFromMap, clipFromLightView;
  vec4 perTexelU, perTexelV, perDepth;  // orthographic views
};
// Written once a frame by accumulation/forward_map_to_clip.comp (mapToClip, below) into a buffer
// the splat passes read as a uniform block (binding 2; LightViews is 1): taken per invocation
// they cost as much as the projections themselves, and read from a storage block each lane
// loads them on its own (llvmpipe).
layout(std140, binding = 2) uniform ForwardMapToClip { MapToClip forwardMapToClip; };

MapToClip mapToClip() {
  MapToClip m;
  float texel = 1.0 / float(u_mapSize);
  mat4 ndcFromMap = mat4(vec4(2.0 * texel, 0, 0, 0), vec4(0, 2.0 * texel, 0, 0), vec4(0, 0, 1, 0), vec4(-1, -1, 0, 1));
  m.rayFromMap = lightViewMatrix[0] * inverse(lightViewProjMatrix[0]) * ndcFromMap;
  m.clipFromLightView = u_eyeViewProj * inverse(lightViewMatrix[0]);
  m.perTexelU = m.clipFromLightView * vec4(m.rayFromMap[0].xy, 0.0, 0.0);
  m.perTexelV = m.clipFromLightView * vec4(m.rayFromMap[1].xy, 0.0, 0.0);
  m.perDepth = m.clipFromLightView * vec4(0.0, 0.0, lightViewRange[0].x - lightViewRange[0].y, 0.0);
  return m;
}

// As lightRayPoint (common/light_ray.glsl) followed by the eye's projection.
vec4 clipOfSample(vec2 texel, float d) {
  vec4 ray = forwardMapToClip.rayFromMap * vec4(texel, 0.0, 1.0);
  float dist = mix(lightViewRange[0].x, lightViewRange[0].y, d);
#ifdef SL_PERSPECTIVE_MAP
  // Along the texel's ray to view distance dist: ray * dist / -ray.z, homogeneous.
  float w = max(-ray.z, 1e-12);
  return forwardMapToClip.clipFromLightView * vec4(ray.xyz * dist, w) / w;
#else
  return forwardMapToClip.clipFromLightView * vec4(ray.xy / ray.w, -dist, 1.0);
#endif
}

// The window offset, in pixels, from the sample (clip position `clip`, centred window position
// `here`) to where a neighbour one texel along `step` lands (its own stored depth, or this one's
// where it is empty); behind the eye: as far as allowed.
vec2 offsetTo(ivec2 t, ivec2 step, float d, vec4 clip, vec2 here) {
  ivec2 n = clamp(t + step, ivec2(0), ivec2(u_mapSize - 1));
  float dn = texelFetch(u_shadowMap, ivec3(n, 0), 0).r;
  dn = dn < 1.0 ? dn : d;
#ifdef SL_PERSPECTIVE_MAP
  vec4 c = clipOfSample(vec2(t + step) + 0.5, dn);
#else
  MapToClip m = forwardMapToClip;
  vec4 c = clip + float(step.x) * m.perTexelU + float(step.y) * m.perTexelV + (dn - d) * m.perDepth;
#endif
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
vec2 splatHalfSides(ivec2 t, float d, vec4 clip, vec2 window) {
  if (u_forward_grow < 0.5) return vec2(0.5 * u_forward_splat);
  vec2 here = window - 0.5 * u_screenSize;  // the centred window position offsetTo measures from
  vec2 alongU = max(abs(offsetTo(t, ivec2(1, 0), d, clip, here)), abs(offsetTo(t, ivec2(-1, 0), d, clip, here)));
  vec2 alongV = max(abs(offsetTo(t, ivec2(0, 1), d, clip, here)), abs(offsetTo(t, ivec2(0, -1), d, clip, here)));
  vec2 half_ = 0.5 * (alongU + alongV) * u_forward_footprint + 0.5;
  return clamp(mix(half_, vec2(0.5 * kMaxSplat), isnan(half_)), vec2(0.5), vec2(0.5 * kMaxSplat));
}

// Zhang compares the sample with the eye's depth buffer; here the pixel's surface point
// (G-buffer) is taken to the light view, where "the same surface" is exact on slopes too: the
// point falls in the sample's texel (forward.footprint texels wide) and is not behind the
// sample's depth beyond the technique's bias, the test a backward map makes. The pixel's side of
// it is its receiver record: where its point falls in the map (texels), its depth less the bias,
// w = 1; w = 0 where no splat may light it (no surface, facing away, outside the map, which
// `offMap` reports: the backward test calls those lit, and so does forward mapping here).
vec4 forwardReceiver(ivec2 pixel, out bool offMap) {
  offMap = false;
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) return vec4(0.0);
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  vec3 F = gbufferFacetNormal(pixel, N);
  vec3 L = directionToLight(P.xyz);
  float cosTheta = dot(N, L);
  if (!surfaceFacesLight(P.xyz, N, F, L)) return vec4(0.0);  // unlit, as the splats leave it
  ShadowCoord sc = layoutShadowCoordIn(biasReceiverPosition(P.xyz, N, cosTheta, 0), 0);
  offMap = shadowCoordOffMap(sc);
  if (offMap || sc.view < 0) return vec4(0.0);
  return vec4(sc.uv * float(u_mapSize), sc.depth - biasDepth(P.xyz, cosTheta, 0), 1.0);
}

// Whether the sample of the texel centred at `texel` with stored depth sampleDepth lights the
// receiver.
bool receiverLit(vec4 receiver, float sampleDepth, vec2 texel) {
  return receiver.w > 0.5 && all(lessThanEqual(abs(receiver.xy - texel), vec2(0.5 * u_forward_footprint))) &&
         receiver.z <= sampleDepth;
}

// The sample of texel t with stored depth d: its eye clip position and window position, and
// false when it lands nowhere (behind the eye; non-finite).
bool sampleLands(ivec2 t, float d, out vec4 clip, out vec2 window) {
  clip = clipOfSample(vec2(t) + 0.5, d);
  // The splat is clipped to the screen, not culled with its centre as GL culls a point: a
  // texel stretched over hundreds of pixels can have its sample off screen while its splat
  // still covers the view (beyond Zhang; low-sun 11.5 % -> 1.6 % wrong at 160x90).
  window = vec2(0.0);
  if (!(clip.w > 1e-6)) return false;  // behind the eye: it lands nowhere
  window = (clip.xy / clip.w * 0.5 + 0.5) * u_screenSize;
  return !any(isnan(window)) && !any(isinf(window));
}

// The splat of texel t: its stored depth d and the pixels whose centres lie in [window - half,
// window + half), the first (lo) and last (hi) on screen; false when it has none (an empty
// texel: nothing was rasterized there; a sample that lands nowhere; a splat off screen).
bool splatOfTexel(ivec2 t, out float d, out ivec2 lo, out ivec2 hi) {
  lo = ivec2(0);
  hi = ivec2(-1);
  d = texelFetch(u_shadowMap, ivec3(t, 0), 0).r;
  if (!(d < 1.0)) return false;
  vec4 clip;
  vec2 window;
  if (!sampleLands(t, d, clip, window)) return false;
  vec2 half_ = splatHalfSides(t, d, clip, window);
  // Clamped as floats: a sample far off screen must not overflow the integer conversion.
  lo = ivec2(clamp(ceil(window - half_ - 0.5), vec2(0.0), u_screenSize));
  hi = ivec2(clamp(ceil(window + half_ - 0.5) - 1.0, vec2(-1.0), u_screenSize - 1.0));
  return all(lessThanEqual(lo, hi));
}

void markLit(ivec2 pixel) { imageStore(u_visibilityOut, pixel, vec4(1.0, 1.0, 0.0, 0.0)); }
