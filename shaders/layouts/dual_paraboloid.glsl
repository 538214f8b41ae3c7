// Dual-paraboloid layout for a point light (techniques/point/dual_paraboloid.cpp; Brabec, Annen &
// Seidel 2002): two views from the light, one per hemisphere, each a layer. A direction d in a
// view's frame (the hemisphere's axis is the view's -z) maps to d.xy / (1 - d.z), the paraboloid
// (stereographic) image: the hemisphere fills the unit disk, scaled by 1 / kParaboloidWindow so
// that filter taps just past the rim read drawn texels, then cropped to the view's fitted window
// (lightViewWindow: the part of the disk where the camera sees receivers, zoomed to fill the
// map; the whole disk when paraboloid.fit is off). Stored depth is the radial distance from
// the light over [near, far]. Casters are tessellated (passes/shadow_paraboloid.tesc) because the
// map bends straight edges into circle arcs. Under a directional or spot light the layout is
// one focused matrix view (lightViewInfo.x == 1) and this module reads it as single_matrix.glsl does.
#define SL_LAYOUT_PICKS_VIEW
#define SL_LAYOUT_CULLS_CASTER_FRAGMENTS
#include "common/light_views.glsl"
uniform float u_shadowMapSize;
uniform int u_shadowView;  // the view the shadow pass rasterizes (passes/shadow.vert)

#include "layouts/paraboloid_image.glsl"
const float kParaboloidMargin = 0.1;   // casters drawn down to this (cos) behind the hemisphere's plane

bool paraboloidViews() { return lightViewInfo.x > 1.5; }

// How many times the view's fitted window magnifies the whole disk along x and y (1: the whole
// disk; the two differ where point.fit_visible fits the axes apart).
vec2 paraboloidZooms(int view) { return lightViewWindow[view].zw; }
// The smaller: the map's largest texel, in units of the whole disk's.
float paraboloidZoom(int view) { return min(lightViewWindow[view].z, lightViewWindow[view].w); }

vec4 layoutClipIn(vec3 worldPos, int view) {
  if (!paraboloidViews()) return lightViewProjMatrix[view] * vec4(worldPos, 1.0);
  vec3 v = (lightViewMatrix[view] * vec4(worldPos, 1.0)).xyz;
  float r = length(v);
  // NaN and the light's own position fail this: w = 0 marks "not in the map".
  if (!(r > 1e-20)) return vec4(0.0, 0.0, 0.0, 0.0);
  vec2 disk = paraboloidDiskImage(v / r);
  vec2 uv = (disk - lightViewWindow[view].xy) * paraboloidZooms(view);
  float depth = (r - lightViewRange[view].x) / (lightViewRange[view].y - lightViewRange[view].x);
  return vec4(uv, depth * 2.0 - 1.0, 1.0);
}

float layoutDepthIn(vec3 worldPos, int view) {
  vec3 v = (lightViewMatrix[view] * vec4(worldPos, 1.0)).xyz;
  float dist = paraboloidViews() ? length(v) : -v.z;
  return (dist - lightViewRange[view].x) / (lightViewRange[view].y - lightViewRange[view].x);
}

vec4 layoutClip(vec3 worldPos) { return layoutClipIn(worldPos, u_shadowView); }
float layoutDepth(vec3 worldPos) { return layoutDepthIn(worldPos, u_shadowView); }

// A caster fragment farther behind the drawn hemisphere than the margin: its image is far off
// the disk, and a tessellated piece reaching toward the opposite pole can cross the map. The
// directions behind the margin form a convex cone, so a piece whose corners all lie in it is
// dropped whole.
bool layoutCullsCasterFragment(vec3 worldPos) {
  if (!paraboloidViews()) return false;
  vec3 v = (lightViewMatrix[u_shadowView] * vec4(worldPos, 1.0)).xyz;
  return v.z > kParaboloidMargin * length(v);
}

ShadowCoord layoutShadowCoordIn(vec3 worldPos, int view) {
  vec4 c = layoutClipIn(worldPos, view);
  if (!(c.w > 1e-6)) return shadowCoordNone();  // NaN fails too
  return ShadowCoord(c.xy / c.w * 0.5 + 0.5, layoutDepthIn(worldPos, view), view, -1, 0.0);
}

// The hemisphere that holds the point: view 0's when it lies in front of view 0's plane.
ShadowCoord layoutShadowCoord(vec3 worldPos) {
  if (!paraboloidViews()) return layoutShadowCoordIn(worldPos, 0);
  float front = -(lightViewMatrix[0] * vec4(worldPos, 1.0)).z;
  return layoutShadowCoordIn(worldPos, front >= 0.0 ? 0 : 1);
}

// World size of one texel at this point, across the ray from the light. A direction theta off the
// axis lands at radius tan(theta / 2) of the disk, which turns by 1 / (1 + cos theta) per
// radian; a texel is 2 kParaboloidWindow / size of that radius, over the window's zoom. (Steps along the view's own x and
// y, as single_matrix.glsl measures perspective maps, both run along the ray for a receiver near
// the rim: the size came out tens of times too large and the slope bias lit the shadows there.)
float layoutTexelWorldSize(vec3 worldPos, int view) {
  float unitTexel = lightViewRange[view].z;
  if (!paraboloidViews()) {
    vec4 c = lightViewProjMatrix[view] * vec4(worldPos, 1.0);  // a focused view: ortho or spot
#ifdef SL_PERSPECTIVE_MAP
    return c.w > 1e-6 ? unitTexel * c.w : unitTexel;
#else
    return unitTexel;
#endif
  }
  vec3 v = (lightViewMatrix[view] * vec4(worldPos, 1.0)).xyz;
  float r = length(v);
  float size = r * 2.0 * kParaboloidWindow / (u_shadowMapSize * paraboloidZoom(view)) * (1.0 - v.z / max(r, 1e-20));
  return isnan(size) || isinf(size) || !(size > 0.0) ? unitTexel : size;
}

// Depth units per world unit along the light direction (radial for the paraboloids).
float layoutDepthScale(int view) { return 1.0 / (lightViewRange[view].y - lightViewRange[view].x); }
