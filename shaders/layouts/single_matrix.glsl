// Layout module for layouts whose views are each one light view and projection (uniform,
// focused, LiSPSM, and each view of a partitioned layout). Stored depth is light-view linear
// depth in [0,1] over [near, far] of the view. SL_PERSPECTIVE_MAP (from the renderer's prelude)
// marks perspective or warped views.
// Contract of a layout module: layoutClip/layoutDepth for the shadow pass (view u_shadowView),
// layoutShadowCoord (picks the view(s) for a point), layoutShadowCoordIn, layoutTexelWorldSize
// and layoutDepthScale per view.
#include "common/light_views.glsl"
#define SL_LAYOUT_DEPTH_AFFINE  // layoutDepth: light-view linear depth (passes/caster_depth.glsl)
// uv is clip.xy / clip.w of the view's matrix (common/receiver_plane.glsl relies on it); not under
// LogPSM's warp, and the dual paraboloid (which includes this module) takes it back.
#ifndef SL_LOG_WARP
#define SL_LAYOUT_PROJECTIVE
#endif
uniform float u_shadowMapSize;
uniform int u_shadowView;  // the view the shadow pass rasterizes (passes/shadow.vert)

vec4 layoutClipIn(vec3 worldPos, int view) {
  vec4 c = lightViewProjMatrix[view] * vec4(worldPos, 1.0);
#ifdef SL_LOG_WARP
  // With LogPSM's perspective part w is the distance from the log's pole (1 at the map's near
  // side), clamped where the log is (t/δ >= -0.999): a point behind the pole is off the map.
  // δ <= 0 (no warp, and a spot light's perspective fallback): the matrix's clip position as is;
  // the warp's y assumes the orthographic basis (w = 1 there), and a spot's w is not 1.
  if (lightViewSplit[view].w > 0.0) {
    c.w = max(c.w, 1e-3);
    c.y = (2.0 * logWarp(c.y * 0.5 + 0.5, lightViewSplit[view].w) - 1.0) * c.w;  // layouts/logpsm.glsl
  }
#endif
  return c;
}

float layoutDepthIn(vec3 worldPos, int view) {
  float z = -(lightViewMatrix[view] * vec4(worldPos, 1.0)).z;
  return (z - lightViewRange[view].x) / (lightViewRange[view].y - lightViewRange[view].x);
}

vec4 layoutClip(vec3 worldPos) { return layoutClipIn(worldPos, u_shadowView); }

#ifdef SL_LOG_WARP
// A caster fragment from behind the log's pole: a triangle reaching behind the viewer, whose
// clamped corner the rasterizer stretched across the map (its fragments interpolate toward that
// corner, w weighted 1/w). The shadow passes drop them (passes/shadow*.frag).
bool layoutBehindPole(vec3 worldPos) { return (lightViewProjMatrix[u_shadowView] * vec4(worldPos, 1.0)).w < 1e-3; }
#endif
float layoutDepth(vec3 worldPos) { return layoutDepthIn(worldPos, u_shadowView); }

ShadowCoord layoutShadowCoordIn(vec3 worldPos, int view) {
  vec4 c = layoutClipIn(worldPos, view);
  // Written so that a NaN position (or w) also counts as "not in the map": NaN fails every
  // comparison, so `c.w <= 1e-6` would let it through.
  if (!(c.w > 1e-6)) return shadowCoordNone();
  // Orthographic clip depth is already the linear depth; only perspective maps need the view.
#ifdef SL_PERSPECTIVE_MAP
  float depth = layoutDepthIn(worldPos, view);
#else
  float depth = c.z * 0.5 + 0.5;
#endif
  return ShadowCoord(c.xy / c.w * 0.5 + 0.5, depth, view, -1, 0.0);
}

#ifndef SL_LAYOUT_PICKS_VIEW
// One view: every point is in view 0 (partitioned layouts define their own picking).
ShadowCoord layoutShadowCoord(vec3 worldPos) { return layoutShadowCoordIn(worldPos, 0); }
#endif

// World size of one texel at this point: what normal offset and slope bias are scaled by.
// Perspective and warped maps (SL_PERSPECTIVE_MAP) measure it from the projection itself, one
// step along each light-plane axis, so every such layout gets it right without its own formula.
float layoutTexelWorldSize(vec3 worldPos, int view) {
  float unitTexel = lightViewRange[view].z;
#ifdef SL_PERSPECTIVE_MAP
  mat4 lv = lightViewMatrix[view];
  vec3 ax = vec3(lv[0][0], lv[1][0], lv[2][0]);
  vec3 ay = vec3(lv[0][1], lv[1][1], lv[2][1]);
  float h = 1e-3 * (lightViewRange[view].y - lightViewRange[view].x);
  vec4 c0 = layoutClipIn(worldPos, view), cx = layoutClipIn(worldPos + ax * h, view),
       cy = layoutClipIn(worldPos + ay * h, view);
  // At or behind the projection's centre plane (a spot light's own plane, behind a warp's
  // centre) the map has no texels: dividing by w there gives Inf/NaN, and bias callers run
  // before the point is rejected. Such points are unlit or outside the map, so any finite size
  // will do; the one at unit distance is what the layout reports.
  if (!(min(c0.w, min(cx.w, cy.w)) > 1e-6)) return unitTexel;
  vec2 p0 = c0.xy / c0.w;
  float texelsPerUnit = 0.5 * u_shadowMapSize / h * min(length(cx.xy / cx.w - p0), length(cy.xy / cy.w - p0));
  float size = 1.0 / max(texelsPerUnit, 1e-6);
  return isnan(size) || isinf(size) ? unitTexel : size;
#else
  return unitTexel;
#endif
}

// Depth units per world unit along the light direction.
float layoutDepthScale(int view) { return 1.0 / (lightViewRange[view].y - lightViewRange[view].x); }
