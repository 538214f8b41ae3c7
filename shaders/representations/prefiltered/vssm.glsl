// Variance soft shadow maps (Yang et al. 2010), the PCSS steps over VSM moments
// (soft_moments.glsl): the blocker depth from the moments of the search box, the penumbra box
// filtered by the summed-area table, Chebyshev's bound as visibility.
#include "representations/prefiltered/moment_math.glsl"
uniform float u_vssm_min_variance;
uniform float u_vssm_bleed;
// Kernel subdivision (Yang et al. 2010): where the whole search box gives no blocker estimate,
// 2^levels x 2^levels sub-boxes are estimated one by one (soft_moments.glsl).
uniform float u_vssm_subdivide;
#define SL_SOFT_SUBDIVIDE_LEVELS u_vssm_subdivide
// The sub-boxes compare with the receiver's plane (its gradient in the map, whatever bias.mode).
#define SL_RECEIVER_PLANE_ALWAYS
#include "common/receiver_plane.glsl"

void representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS]) { m[0] = vec4(z, z * z, 0.0, 0.0); }

float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  return reduceLightBleeding(chebyshevUpperBound(m[0].xy, receiverDepth, u_vssm_min_variance), u_vssm_bleed);
}

float representationVariance(vec4 m[SL_MOMENT_TARGETS]) { return m[0].y - m[0].x * m[0].x; }

// Yang et al.'s estimate: Chebyshev's bound read as the fraction N of the box at or beyond the
// receiver, those texels assumed at the receiver's depth d, so mean = N d + (1 - N) z_blocker.
// Exact for one planar blocker over a planar receiver. A receiver nearer than the mean gets no
// bound (N = 1, no blocker): the paper's known failure where a receiver falls away behind the
// blockers, which it answers by subdividing the kernel (vssm.subdivide, soft_moments.glsl).
vec2 representationBlocker(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  float mean = m[0].x;
  if (!(receiverDepth > mean)) return vec2(0.0, receiverDepth);
  float lit = chebyshevUpperBound(m[0].xy, receiverDepth, u_vssm_min_variance);
  float blocked = 1.0 - lit;
  return vec2(blocked, (mean - lit * receiverDepth) / max(blocked, 1e-4));
}

float representationSoftVisibility(vec4 m[SL_MOMENT_TARGETS], float receiverDepth, float gap) {
  return representationFromMoments(m, receiverDepth);
}
#include "representations/prefiltered/soft_moments.glsl"
