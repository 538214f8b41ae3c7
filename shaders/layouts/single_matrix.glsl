// Layout module for layouts described by one light view and projection (uniform, focused;
// later warped ones). Stored depth is light-view linear depth in [0,1] over [near, far].
// SL_PERSPECTIVE_MAP (from the renderer's prelude) marks a perspective (spot) map.
uniform mat4 u_lightView;
uniform mat4 u_lightViewProj;
uniform float u_lightNear;
uniform float u_lightFar;
uniform float u_lightTexelWorld;    // world size of a texel (at unit distance when perspective)
uniform float u_shadowMapSize;

vec4 layoutClip(vec3 worldPos) { return u_lightViewProj * vec4(worldPos, 1.0); }

float layoutDepth(vec3 worldPos) {
  float z = -(u_lightView * vec4(worldPos, 1.0)).z;
  return (z - u_lightNear) / (u_lightFar - u_lightNear);
}

// xy: shadow-map uv in [0,1]; z: depth in [0,1]; w: 0 when the point is behind a spot light.
vec4 layoutProject(vec3 worldPos) {
  vec4 c = layoutClip(worldPos);
  // Written so that a NaN position (or w) also counts as "not in the map": NaN fails every
  // comparison, so `c.w <= 1e-6` would let it through.
  if (!(c.w > 1e-6)) return vec4(0.0, 0.0, 0.0, 0.0);
  // Orthographic clip depth is already the linear depth; only perspective maps need the view.
#ifdef SL_PERSPECTIVE_MAP
  float depth = layoutDepth(worldPos);
#else
  float depth = c.z * 0.5 + 0.5;
#endif
  return vec4(c.xy / c.w * 0.5 + 0.5, depth, 1.0);
}

// World size of one texel at this point: what normal offset and slope bias are scaled by.
// Perspective and warped maps (SL_PERSPECTIVE_MAP) measure it from the projection itself, one
// step along each light-plane axis, so every such layout gets it right without its own formula.
float layoutTexelWorldSize(vec3 worldPos) {
#ifdef SL_PERSPECTIVE_MAP
  vec3 ax = vec3(u_lightView[0][0], u_lightView[1][0], u_lightView[2][0]);
  vec3 ay = vec3(u_lightView[0][1], u_lightView[1][1], u_lightView[2][1]);
  float h = 1e-3 * (u_lightFar - u_lightNear);
  vec4 c0 = layoutClip(worldPos), cx = layoutClip(worldPos + ax * h), cy = layoutClip(worldPos + ay * h);
  // At or behind the projection's centre plane (a spot light's own plane, behind a warp's
  // centre) the map has no texels: dividing by w there gives Inf/NaN, and bias callers run
  // before layoutProject rejects the point. Such points are unlit or outside the map, so any
  // finite size will do; the one at unit distance is what the layout reports.
  if (!(min(c0.w, min(cx.w, cy.w)) > 1e-6)) return u_lightTexelWorld;
  vec2 p0 = c0.xy / c0.w;
  float texelsPerUnit = 0.5 * u_shadowMapSize / h * min(length(cx.xy / cx.w - p0), length(cy.xy / cy.w - p0));
  float size = 1.0 / max(texelsPerUnit, 1e-6);
  return isnan(size) || isinf(size) ? u_lightTexelWorld : size;
#else
  return u_lightTexelWorld;
#endif
}

// Depth units per world unit along the light direction.
float layoutDepthScale() { return 1.0 / (u_lightFar - u_lightNear); }
