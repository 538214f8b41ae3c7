// The light views of the technique's layout (1..8, one shadow-map layer each), one uniform block
// uploaded by the renderer (app/render/light_views_buffer.cpp). Block members are not
// parameters, so they carry no u_ prefix.
#define SL_MAX_LIGHT_VIEWS 8
layout(std140, binding = 1) uniform LightViews {
  mat4 lightViewMatrix[SL_MAX_LIGHT_VIEWS];
  mat4 lightViewProjMatrix[SL_MAX_LIGHT_VIEWS];
  vec4 lightViewRange[SL_MAX_LIGHT_VIEWS];  // near, far (light-view distances), texel world size, perspective
  vec4 lightViewSplit[SL_MAX_LIGHT_VIEWS];  // camera view depth the view serves: from, to, blend band; w: LogPSM delta
  vec4 lightViewWindow[SL_MAX_LIGHT_VIEWS];  // a paraboloid's fitted window: map = (disk - xy) * zw
  // x: the layer the view is drawn into, y: its packed triangle (-1: none), zw: where its layer's
  // image lies in a layer shared by several lights (LightSpace::atlasPlacement; 0 alone)
  vec4 lightViewPacking[SL_MAX_LIGHT_VIEWS];
  vec4 lightViewAtlas[SL_MAX_LIGHT_VIEWS];    // the view's square of an atlas layer in uv: min xy, max xy; 0: none
  vec4 lightViewInfo;  // x: number of views, y: texels per side, z: the layer image's scale in a shared layer (1 alone)
};

// The shadow-map layer view `view` reads and writes: its index, unless views share a layer
// (LightView::layer, Liao's packed tetrahedron).
float lightViewLayer(int view) { return lightViewPacking[view].x; }

// Which side of a packed view's triangle a point of its layer is on (LightView::packedTriangle):
// the layer's square split by its diagonals, 0 top, 1 right, 2 bottom, 3 left. ndc: the point in
// the layer's [-1, 1] square, or a clip position (the tests are linear, so w > 0 may stay). Both
// >= 0 inside; a view that owns the whole layer is inside everywhere.
// A clip position in the layer the views are drawn into, back in their own layer's square: the
// same unless the light's layer is a region of one shared by several lights.
vec2 lightViewOwnClip(vec4 clip) { return (clip.xy - lightViewPacking[0].zw * clip.w) / lightViewInfo.z; }

vec2 packedTriangleSides(vec2 ndc, int view) {
  int triangle = int(lightViewPacking[view].y + 0.5);
  if (lightViewPacking[view].y < -0.5) return vec2(1.0);
  // Turned so that the triangle is the top one, y >= |x|.
  vec2 p = triangle == 1 ? vec2(-ndc.y, ndc.x) : triangle == 2 ? -ndc : triangle == 3 ? vec2(ndc.y, -ndc.x) : ndc;
  return vec2(p.y - p.x, p.y + p.x);
}

// Filter taps around a lookup in view `view` (uv of its layer of mapSize texels), kept inside the
// view's square when the view has one in an atlas layer (LightView::atlasRect): past the square
// lie another face's depths, which mean nothing here, while its own edge texel (in the border
// drawn past the face's window) is what a layer of its own would clamp the tap to. Views that own
// their layer are left alone (their sampler's wrap decides).
// A filter takes the range once (lightViewTapRange) and clamps each tap to it (lightViewTapIn):
// per tap, the view's square read by a varying index cost llvmpipe half of `pcf`'s shading pass.
vec4 lightViewTapRange(int view, vec2 mapSize) {
  vec4 square = lightViewAtlas[view];
  if (!(square.z > square.x)) return vec4(vec2(-1e30), vec2(1e30));  // no square: taps as they are
  vec2 halfTexel = 0.5 / mapSize;
  return vec4(square.xy + halfTexel, square.zw - halfTexel);
}

vec2 lightViewTapIn(vec2 uv, vec4 range) { return clamp(uv, range.xy, range.zw); }

// One tap alone.
vec2 lightViewTap(vec2 uv, int view, vec2 mapSize) { return lightViewTapIn(uv, lightViewTapRange(view, mapSize)); }

// The view of the last map lookup the visibility test set up (common/visibility_term.glsl,
// representations/soft/receiver_coord.glsl): a representation is handed uv and layer, and reads
// per-view values (depth range, texel size) of this view.
int sl_view = 0;

// Where a point falls in the shadow map, as a layout's module reports it.
struct ShadowCoord {
  vec2 uv;        // in [0,1] on the view's layer
  float depth;    // the point's stored-depth value in that view, [0,1]
  int view;       // the light view (lightViewLayer gives its layer); -1 when no view can see the point (behind a perspective light)
  int view2;      // a second view to blend with (partition borders), -1 = none
  float weight2;  // weight of view2's test, 0..1
};

ShadowCoord shadowCoordNone() { return ShadowCoord(vec2(0.0), 0.0, -1, -1, 0.0); }

// No texel of the map holds the point (no view sees it, or it falls outside the view's layer):
// nothing was drawn there as a caster, so the tests call it lit.
bool shadowCoordOffMap(ShadowCoord sc) {
  return sc.view < 0 || any(lessThan(sc.uv, vec2(0.0))) || any(greaterThan(sc.uv, vec2(1.0)));
}

// The view's map holds the point: what a layout that picks among views checks before falling
// back to another (a NaN position counts as not held, unlike shadowCoordOffMap's "lit").
bool shadowCoordOnMap(ShadowCoord sc) {
  return sc.view >= 0 && all(greaterThanEqual(sc.uv, vec2(0.0))) && all(lessThanEqual(sc.uv, vec2(1.0)));
}
