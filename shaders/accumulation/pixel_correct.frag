// Pixel-correct shadow maps (Scherzer, Jeschke, Wimmer, EGSR 2007) in the scene pass, as in the
// paper: the previous-frame position comes from the vertex shader (eq. 4, with each object's
// previous transform for moving objects), and colour and history are written together with
// multiple render targets.
//   f(n) = this frame's shadow test, conf (eq. 5), w = conf^m (eq. 6)
//   s(n) = a f(n) + (1 - a) s(n-1)       (eq. 2/3), s(n) = f(n) where there is no history
//   a    = w (the paper), or with pc.warmup a = w / (W + w), W = accumulated weight
//          (min(sum of w, 1), shrunk when the history was interpolated between texels): a
//          confidence-weighted mean whose memory is capped and fades under reprojection blur;
//          or with pc.keep_best a = 1 when w beats the best weight W so far, else 0;
//          or with pc.area_light (each frame a different point of the light) a = 1 / (frames + 1),
//          the plain mean over at most pc.area_frames frames (W = frames / pc.area_frames).
// Needs the technique prelude (layout + representation modules).
#include "common/surface.glsl"
#include "common/visibility_term.glsl"
#include "common/shading.glsl"
#include "accumulation/pixel_correct.glsl"

uniform float u_m;
uniform float u_pc_area_frames;

layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_history;  // r: s(n) (also what is shown), g: linear view depth (0 = none), b: W
#ifdef PC_WRITE_RAW
layout(location = 2) out vec2 o_raw;  // this frame's test and confidence, for the views and readback
#endif

void main() {
  vec3 F = surfaceFacetNormal();
  materialAlphaTest(v_uv);
  vec3 P = v_world, N = surfaceNormal();
  vec4 coord;
  vec2 raw = visibilityTermAt(P, N, F, coord);
  float f = raw.x;
  float c = pcFinite(raw.y) ? clamp(raw.y, 0.0, 1.0) : 0.0;
  vec4 motion = v_prevClip.w > 1e-6 ? vec4(v_prevClip.xyz / v_prevClip.w, 1.0) : vec4(0.0);
  PcHistory h = pcHistoryFrom(motion, v_prevViewDepth, coord, f, c);
  float w = pow(c, max(u_m, 1e-3));
  float s = f;
  float a = 1.0, W = w;
#ifdef PC_AREA_LIGHT
  // pc.area_light: every frame tests one point of the light's disk, so the area light's
  // visibility is the plain mean of the tests; W holds the frames averaged over pc.area_frames.
  W = 1.0 / u_pc_area_frames;
#endif
  if (h.state == PC_VALID) {
#if defined(PC_AREA_LIGHT)
    float frames = h.W * u_pc_area_frames;
    a = 1.0 / (frames + 1.0);
    W = min(frames + 1.0, u_pc_area_frames) / u_pc_area_frames;
#elif defined(PC_KEEP_BEST)
    // pc.keep_best, the m -> infinity limit of eq. 6: the most confident test so far wins
    // outright; W holds its weight (shrunk when the history is resampled between texels).
    a = w > h.W ? 1.0 : 0.0;
    W = max(h.W, w);
#else
    a = u_pc_warmup > 0.5 ? (h.W + w > 0.0 ? w / (h.W + w) : 1.0) : w;
    W = min(h.W + w, 1.0);
#endif
    s = clamp(a * f + (1.0 - a) * h.s, 0.0, 1.0);
  }
  if (!pcFinite(s)) s = h.state == PC_VALID ? h.s : 1.0;
  float depth = pcLinearDepth(P);
#ifdef PC_WRITE_RAW
  o_raw = raw;
#endif
  o_history = vec4(s, pcFinite(depth) && depth > 0.0 ? depth : 0.0, W, 0.0);
  o_color = shadeSurface(materialColor(v_uv).rgb, P, N, s);
}
