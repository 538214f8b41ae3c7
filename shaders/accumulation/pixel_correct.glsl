// Pixel-correct shadow maps (Scherzer et al. 2007): history lookup shared by the update pass
// and its debug views. The history buffer holds r = s(n-1), g = linear view depth of the
// previous frame (0 = nothing there), b = accumulated confidence weight W (for pc.warmup).
#ifdef SL_DEFERRED
uniform sampler2D u_gPosition;  // world position, w = 1 covered (views)
#endif
uniform sampler2D u_gMotion;    // previous-frame NDC of this pixel's surface point, w = 1 valid
uniform sampler2D u_raw;        // r = f(n) (this frame's test), g = confidence (eq. 5); views only
uniform sampler2D u_history;    // previous frame's history
uniform float u_hasHistory;     // 0 after a cut / on the first frame
uniform mat4 u_view;            // current camera view
uniform mat4 u_invPrevProj;     // inverse of the previous frame's projection
uniform float u_pc_disocclusion;
uniform float u_pc_warmup;
uniform float u_pc_reject;
uniform float u_pc_reject_confidence;

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

// Looks this point up in the previous frame (eq. 4, generalised to moving objects by each
// instance's previous transform) with the hardware's bilinear filter, as the paper does. The
// filtered depth must match the depth the point had in the previous frame: across a depth edge
// the filter mixes depths and the test fails, which is the disocclusion case.
// Bilinear (the paper) or Catmull-Rom (pc.history_filter): resampling the history every frame
// with a bilinear filter blurs it a little more each frame while the camera moves (edges lag);
// the Catmull-Rom spline keeps them sharp. Nine bilinear taps give the 4x4 spline.
// PC_CATMULL_ROM comes from the pass's prelude (a software rasterizer runs both sides of a
// uniform branch, so the nine taps would cost even when unused).
vec3 pcHistorySample(vec2 uv) {
#ifndef PC_CATMULL_ROM
  return texture(u_history, uv).rgb;
#else
  vec2 size = vec2(textureSize(u_history, 0));
  vec2 p = uv * size;
  vec2 t1 = floor(p - 0.5) + 0.5;
  vec2 f = p - t1;
  vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
  vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
  vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
  vec2 w3 = f * f * (-0.5 + 0.5 * f);
  vec2 w12 = w1 + w2;
  vec2 c0 = (t1 - 1.0) / size, c12 = (t1 + w2 / w12) / size, c3 = (t1 + 2.0) / size;
  vec3 r = (texture(u_history, vec2(c0.x, c0.y)).rgb * w0.x + texture(u_history, vec2(c12.x, c0.y)).rgb * w12.x +
            texture(u_history, vec2(c3.x, c0.y)).rgb * w3.x) * w0.y;
  r += (texture(u_history, vec2(c0.x, c12.y)).rgb * w0.x + texture(u_history, vec2(c12.x, c12.y)).rgb * w12.x +
        texture(u_history, vec2(c3.x, c12.y)).rgb * w3.x) * w12.y;
  r += (texture(u_history, vec2(c0.x, c3.y)).rgb * w0.x + texture(u_history, vec2(c12.x, c3.y)).rgb * w12.x +
        texture(u_history, vec2(c3.x, c3.y)).rgb * w3.x) * w3.y;
  // The spline overshoots next to edges (ringing that flickers as the sub-pixel offset changes):
  // clamp to the range of the four texels the bilinear filter would have mixed.
  ivec2 i0 = clamp(ivec2(t1), ivec2(0), ivec2(size) - 1), i1 = clamp(ivec2(t1) + 1, ivec2(0), ivec2(size) - 1);
  vec3 a = texelFetch(u_history, i0, 0).rgb, b = texelFetch(u_history, ivec2(i1.x, i0.y), 0).rgb;
  vec3 c = texelFetch(u_history, ivec2(i0.x, i1.y), 0).rgb, d = texelFetch(u_history, i1, 0).rgb;
  return clamp(r, min(min(a, b), min(c, d)), max(max(a, b), max(c, d)));
#endif
}

// m: previous-frame NDC (xyz), w = 1 when valid; expected: previous linear view depth.
PcHistory pcLookupFrom(vec4 m, float expected) {
  PcHistory h;
  h.s = 0.0;
  h.W = 0.0;
  h.state = PC_NONE;
  if (u_hasHistory < 0.5) return h;
  h.state = PC_OFFSCREEN;
  if (m.w < 0.5 || !pcFinite(m.x) || !pcFinite(m.y) || !pcFinite(m.z)) return h;
  if (abs(m.z) > 1.0 || any(greaterThan(abs(m.xy), vec2(1.0)))) return h;  // outside the previous frustum
  if (!pcFinite(expected) || expected <= 0.0) return h;
  vec3 tap = pcHistorySample(m.xy * 0.5 + 0.5);
  h.state = PC_DISOCCLUDED;
  if (!(tap.y > 0.0) || abs(tap.y - expected) > u_pc_disocclusion * expected) return h;
  h.s = clamp(tap.x, 0.0, 1.0);
  // A history value interpolated between texels is a weaker estimate for this exact point than
  // one read on a texel centre: its accumulated weight shrinks by the bilinear weights' sum of
  // squares (1 on a centre, 1/16 halfway in both axes), so a moving camera lets fresh tests in.
  vec2 fr = fract((m.xy * 0.5 + 0.5) * vec2(textureSize(u_history, 0)) - 0.5);
  vec2 sq = (1.0 - fr) * (1.0 - fr) + fr * fr;
#ifdef PC_KEEP_BEST
  const bool decay = true;
#else
  bool decay = u_pc_warmup > 0.5;
#endif
  h.W = clamp(tap.z, 0.0, 1.0) * (decay ? sq.x * sq.y : 1.0);
  h.state = PC_VALID;
  return h;
}

// Beyond the paper, for moving casters: a test that disagrees with the history by more than
// u_pc_reject replaces it when it is unambiguous: confident, or the same at the four shadow-map
// positions one texel around it (the test's own input would not change under any jitter, so the
// history is stale: a caster moved). Needs the technique modules (visibility_term.glsl).
bool pcRejectHistory(vec4 coord, float f, float c, float history) {
  if (u_pc_reject >= 1.0 || abs(f - history) <= u_pc_reject) return false;
  if (c >= u_pc_reject_confidence) return true;
#ifdef PC_REJECT_NEIGHBOURS
  return visibilityUnambiguous(coord, f);
#else
  return false;
#endif
}

// History for the update, with the rejection rule applied; coord from visibilityTermAt.
PcHistory pcHistoryFrom(vec4 motion, float expected, vec4 coord, float f, float c) {
  PcHistory h = pcLookupFrom(motion, expected);
  if (h.state == PC_VALID && pcRejectHistory(coord, f, c, h.s)) h.state = PC_REJECTED;
  return h;
}

#ifdef SL_DEFERRED
// For the debug views, from the G-buffer: motion from gMotion, the previous depth from it.
PcHistory pcHistory(ivec2 pixel, vec3 P, vec3 N, float f, float c) {
  vec4 m = texelFetch(u_gMotion, pixel, 0);
  vec4 v = u_invPrevProj * vec4(m.xyz, 1.0);
  float expected = abs(v.w) > 1e-20 ? -v.z / v.w : -1.0;
  vec4 coord;
  visibilityTermAt(P, N, gbufferFacetNormal(pixel, N), coord);
  return pcHistoryFrom(m, expected, coord, f, c);
}
#endif
