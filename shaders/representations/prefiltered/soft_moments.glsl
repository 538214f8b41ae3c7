// Soft shadows from a pre-filtered map, in the steps of PCSS (Fernando 2005) with both filters
// read from the summed-area table (any box width at the cost of four reads per target):
//   1. the moments over the region that can hold the receiver's blockers (the penumbra model's
//      search radius, representations/soft/penumbra.glsl);
//   2. from them, the fraction of that region nearer than the receiver and its mean depth
//      (representationBlocker: CSM-Z for convolution-soft, Yang et al. 2010's estimate for vssm);
//   3. the penumbra width from that depth by similar triangles;
//   4. the moments over the penumbra box, reconstructed (representationSoftVisibility).
// No search pass and no Poisson taps: the whole search is one box read, which is what these
// papers are for. The module including this file defines, before it:
//   vec2  representationBlocker(vec4 m[SL_MOMENT_TARGETS], float receiverDepth)
//         x: fraction of the box nearer than the receiver, y: their mean stored depth
//   float representationSoftVisibility(vec4 m[SL_MOMENT_TARGETS], float receiverDepth, float gap)
//         gap: receiver-to-blocker distance along the light (world units)
// Without an area light (SL_AREA_LIGHT undefined) the lookup is the hard reconstruction over a
// box of the minimum kernel, read from the moments themselves (no table is made then).
#define SL_MOMENT_SOFT
#include "representations/prefiltered/moment_maps.glsl"
#include "representations/soft/penumbra.glsl"

// A smaller blocker fraction counts as none: the reconstructions' ringing and rounding leave a
// few per cent where nothing blocks, and their mean depth is then noise.
const float kSoftMinBlockerFraction = 0.02;

// Kernel subdivision (Yang et al. 2010, for VSSM; SL_SOFT_SUBDIVIDE_LEVELS from the module): when
// the whole search box gives no blocker (a receiver not beyond the box's mean depth: one that
// falls away behind its blockers, or blockers at several depths), the box is split into k x k
// sub-boxes (k = 2^levels, at most 4) and each is estimated alone; the blocked fraction is their
// mean and the blocker gap their blocked-weighted mean. A box with an estimate keeps it.
// Each sub-box is compared with the receiver's plane at its centre (sl_receiverPlane, set by the
// visibility term when the module defines SL_RECEIVER_PLANE_ALWAYS), not with the pixel's own
// depth: over a planar receiver the mean of a sub-box is that plane depth, so ground sloped in
// the light's view no longer reads as its own blocker in the sub-boxes beyond the pixel.
// Sub-boxes narrower than this are not used (the level drops): a box read from the 32-bit table
// is a difference of sums over up to the whole map, and their rounding over a small box's area
// moves the mean depth by more than the variance floor tolerates (false blockers in streaks).
const float kSoftMinSubBoxTexels = 8.0;
vec2 softBlocker(vec3 uvLayer, float width, float receiverDepth) {
  vec4 m[SL_MOMENT_TARGETS];
  momentsInBox(uvLayer, width, m);
  vec2 whole = representationBlocker(m, receiverDepth);
#ifdef SL_SOFT_SUBDIVIDE_LEVELS
  int k = 1 << int(clamp(SL_SOFT_SUBDIVIDE_LEVELS + 0.5, 0.0, 2.0));
  while (k > 1 && width / float(k) < kSoftMinSubBoxTexels) k /= 2;
  if (k == 1 || whole.x >= kSoftMinBlockerFraction) return whole;
  vec2 texel = 1.0 / vec2(textureSize(u_moments0, 0).xy);
  float blocked = 0.0, weightedGap = 0.0;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      if (i >= k || j >= k) continue;
      vec2 offset = (vec2(i, j) + 0.5 - 0.5 * float(k)) * (width / float(k)) * texel;
      float planeDepth = clamp(receiverDepth + dot(sl_receiverPlane.zw, offset), 0.0, 1.0);
      momentsInBox(vec3(uvLayer.xy + offset, uvLayer.z), width / float(k), m);
      vec2 b = representationBlocker(m, planeDepth);
      if (!(b.x >= kSoftMinBlockerFraction)) continue;  // none here (or NaN)
      blocked += b.x;
      weightedGap += b.x * max(planeDepth - b.y, 0.0);
    }
  if (blocked > 0.0) return vec2(blocked / float(k * k), receiverDepth - weightedGap / blocked);
#endif
  return whole;
}

// x: blocker fraction of the search box, y: their mean stored depth, z: penumbra radius and w:
// search radius (texels of the view read).
vec4 softMomentPenumbra(vec3 uvLayer, float receiverDepth) {
  int view = sl_view;
  float dR = pcssLinear(receiverDepth, view);
  float search = pcssSearchTexels(view, dR);
  vec2 b = softBlocker(uvLayer, 2.0 * search, receiverDepth);
  // NaN fails every comparison: a broken estimate reads as no blocker.
  if (!(b.x >= kSoftMinBlockerFraction)) return vec4(0.0, receiverDepth, kPcssMinRadius, search);
  float blocker = clamp(b.y, 0.0, receiverDepth);
  float r = pcssPenumbraWorld(dR, pcssLinear(blocker, view)) / pcssTexelWorld(view, dR);
  r = isnan(r) ? kPcssMinRadius : clamp(r, kPcssMinRadius, u_pcss_max_radius);
  return vec4(min(b.x, 1.0), blocker, r, search);
}

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  vec4 m[SL_MOMENT_TARGETS];
#ifdef SL_AREA_LIGHT
  vec4 p = softMomentPenumbra(uvLayer, receiverDepth);
  if (p.x < kSoftMinBlockerFraction) return 1.0;  // nothing in the region that sees the light
  momentsInBox(uvLayer, 2.0 * p.z, m);
  int view = sl_view;
  float gap = pcssLinear(receiverDepth, view) - pcssLinear(p.y, view);
  float v = representationSoftVisibility(m, receiverDepth, gap);
#else
  // kPcssMinRadius = 1: a box two texels wide, from the moments themselves where the filter
  // pass made no table (under a point of light: MomentMapState::summed_).
#ifdef SL_MOMENT_SAT
  momentsInBox(uvLayer, 2.0 * kPcssMinRadius, m);
#else
  momentsInTwoTexelBox(uvLayer, m);
#endif
  float v = representationFromMoments(m, receiverDepth);
#endif
  return isnan(v) ? 1.0 : clamp(v, 0.0, 1.0);
}

// Moment reconstructions read a planar receiver under its own box as lit (its mean is its
// depth), so the slope bias needs only the minimum kernel's reach.
float representationFilterRadius(vec3 p, int view) { return kPcssMinRadius; }
