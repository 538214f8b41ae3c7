// Pixel-correct shadow maps (Scherzer et al. 2007): history lookup shared by the update pass
// and its debug views. The history buffer holds r = s(n-1), g = linear view depth of the
// previous frame (0 = nothing there), b = accumulated confidence weight W (for pc.warmup).
uniform sampler2D u_gPosition;  // world position, w = 1 covered
uniform sampler2D u_gMotion;    // previous-frame NDC of this pixel's surface point, w = 1 valid
uniform sampler2D u_raw;        // r = f(n) (this frame's test), g = confidence (eq. 5); views only
uniform sampler2D u_history;    // previous frame's history
uniform float u_hasHistory;     // 0 after a cut / on the first frame
uniform mat4 u_view;            // current camera view
uniform mat4 u_invPrevProj;     // inverse of the previous frame's projection
uniform float u_pc_disocclusion;
uniform float u_pc_reject;
uniform float u_pc_reject_confidence;
uniform float u_pc_reject_neighbours;

const int PC_VALID = 0;        // history found and used
const int PC_NONE = 1;         // no history at all (first frame, cut)
const int PC_OFFSCREEN = 2;    // reprojects outside the previous frame, behind it, or beyond its far plane
const int PC_DISOCCLUDED = 3;  // the previous frame saw another surface there (depth test)
const int PC_REJECTED = 4;     // history disagrees with an unambiguous current test (moving casters)

struct PcHistory {
  float s;    // s(n-1), bilinear over the accepted taps
  float W;    // accumulated weight, min(sum of w, 1)
  int state;  // PC_*
};

bool pcFinite(float x) { return !(isnan(x) || isinf(x)); }

float pcLinearDepth(vec3 world) { return -(u_view * vec4(world, 1.0)).z; }

// Looks this pixel's surface point up in the previous frame (eq. 4 generalised to moving objects
// by the per-instance motion in u_gMotion) with bilinear weights; each of the four taps is kept
// only when its stored depth matches the depth the point had in the previous frame.
PcHistory pcLookup(ivec2 pixel) {
  PcHistory h;
  h.s = 0.0;
  h.W = 0.0;
  h.state = PC_NONE;
  if (u_hasHistory < 0.5) return h;
  h.state = PC_OFFSCREEN;
  vec4 m = texelFetch(u_gMotion, pixel, 0);
  if (m.w < 0.5 || !pcFinite(m.x) || !pcFinite(m.y) || !pcFinite(m.z)) return h;
  if (abs(m.z) > 1.0) return h;  // before the previous near plane or beyond its far plane
  vec2 size = vec2(textureSize(u_history, 0));
  vec2 pos = (m.xy * 0.5 + 0.5) * size - 0.5;  // in texel-centre units
  if (any(lessThan(pos, vec2(-0.5))) || any(greaterThan(pos, size - 0.5))) return h;
  vec4 v = u_invPrevProj * vec4(m.xyz, 1.0);
  if (abs(v.w) < 1e-20) return h;
  float expected = -v.z / v.w;  // view depth of the point in the previous frame
  if (!pcFinite(expected) || expected <= 0.0) return h;

  // A still camera lands on texel centres up to rounding: read them exactly (no blur).
  vec2 base = floor(pos);
  vec2 fr = pos - base;
  vec2 snapped = round(fr);
  fr = mix(fr, snapped, vec2(lessThan(abs(fr - snapped), vec2(1e-3))));
  float sum = 0.0, sumW = 0.0, weight = 0.0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      ivec2 t = ivec2(base) + ivec2(i, j);
      float wt = (i == 0 ? 1.0 - fr.x : fr.x) * (j == 0 ? 1.0 - fr.y : fr.y);
      if (wt <= 0.0 || any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, ivec2(size)))) continue;
      vec3 tap = texelFetch(u_history, t, 0).rgb;
      if (!pcFinite(tap.x) || !pcFinite(tap.y) || !pcFinite(tap.z) || tap.y <= 0.0) continue;
      if (abs(tap.y - expected) > u_pc_disocclusion * expected) continue;
      sum += wt * tap.x;
      sumW += wt * tap.z;
      weight += wt;
    }
  h.state = PC_DISOCCLUDED;
  if (weight < 0.05) return h;
  h.s = clamp(sum / weight, 0.0, 1.0);
  h.W = clamp(sumW / weight, 0.0, 1.0);
  h.state = PC_VALID;
  return h;
}

// Beyond the paper, for moving casters: a test that disagrees with the history by more than
// u_pc_reject replaces it when it is unambiguous: confident, or the same at the four shadow-map
// positions one texel around it (the test's own input would not change under any jitter, so the
// history is stale: a caster moved). Needs the technique modules (visibility_term.glsl).
bool pcRejectHistory(vec3 P, vec3 N, float f, float c, float history) {
  if (u_pc_reject >= 1.0 || abs(f - history) <= u_pc_reject) return false;
  if (c >= u_pc_reject_confidence) return true;
  return u_pc_reject_neighbours > 0.5 && visibilityUnambiguous(P, N, f);
}

// History for the update, with the rejection rule applied.
PcHistory pcHistory(ivec2 pixel, vec3 P, vec3 N, float f, float c) {
  PcHistory h = pcLookup(pixel);
  if (h.state == PC_VALID && pcRejectHistory(P, N, f, c, h.s)) h.state = PC_REJECTED;
  return h;
}
