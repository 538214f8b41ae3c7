// The light-view data a layout computes and every part reads: one view per shadow-map layer
// (matrices, planes, window, texel size, split band, projection kind), the jitter an
// accumulation asks of the rasterization, and what a layout's compute() is given.
#pragma once

#include "core/params.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace sl {

// Sub-texel change of the rasterization requested by an accumulation (pixel-correct jitter).
struct LayoutJitter {
  glm::vec2 offsetTexels{0.0f};
  float rotationRad = 0.0f;
  // A point of the area light's disk, in the unit disk (0 = its centre): layouts build the light
  // frame from the light moved there (layoutLight), so a history over frames integrates the
  // disk (pixel-correct-soft). No effect when light.radius is 0.
  glm::vec2 lightSample{0.0f};
};

// One light view: what one layer of the shadow map sees. Depth stored in the map is always the
// light-view linear depth mapped to [0,1] over [nearPlane, farPlane], whatever the projection,
// so biases mean the same thing in every layout.
struct LightView {
  glm::mat4 view{1.0f};
  glm::mat4 proj{1.0f};
  glm::mat4 viewProj{1.0f};
  bool perspective = false;
  float nearPlane = 0.1f;
  float farPlane = 100.0f;
  glm::vec2 windowMin{-1.0f}, windowMax{1.0f};  // orthographic window in light-view units
  // World size of one texel: orthographic = constant; perspective = this times view distance.
  float texelWorldSize = 0.01f;
  // Camera view depths this view serves (partitioned layouts pick a view per pixel by them) and
  // the width of the band, before splitFar, blended with the next view.
  float splitNear = 0.0f, splitFar = 1e30f, blendBand = 0.0f;
  // > 0: a logarithmic warp of the map's y after the projection (LogPSM, layouts/logpsm.h):
  // y in [-1, 1] -> 2 ln(1 + t/logDelta) / ln(1 + 1/logDelta) - 1 with t = (y + 1) / 2.
  float logDelta = 0.0f;
  // How casters reach the view: through viewProj alone, bent by the log warp after it, or by a
  // paraboloid of one hemisphere around the light (the shadow pass then tessellates casters so
  // their edges follow the bend; shadow_draw_plan.h).
  enum class Projection { Matrix, LogWarp, Paraboloid };
  Projection projection = Projection::Matrix;
  // A LogWarp view's casters are sorted before the shadow pass, those none of whose edges need
  // pieces drawn without the tessellation stages (ShadowDrawPlan::sortStage; logpsm.sort_casters).
  bool sortCasters = false;
  // A paraboloid view's window fitted to what the camera sees of its hemisphere: map xy = (disk
  // xy - .xy) * .zw, disk xy the hemisphere's image scaled by 1 / kParaboloidWindow (below); .zw
  // the zoom along x and y, equal unless point.fit_visible fits the axes apart.
  // (0, 0, 1, 1): the whole disk.
  glm::vec4 paraboloidWindow{0.0f, 0.0f, 1.0f, 1.0f};
  // A convex polygon in map uv (layer 0) holding every receiver this view serves (the focused
  // fit's body, projected), so that a pass over the map may skip texels no visible pixel reads
  // (the moment maps' blur). Empty: not known, every texel may be read.
  std::vector<glm::vec2> receiverHull;
  // Views packed into one layer (Liao 2010's tetrahedron): the layer this view is drawn into and
  // read from (-1: its own index), and which triangle of that layer, split by its diagonals, it
  // owns (-1: the whole layer; 0 top, 1 right, 2 bottom, 3 left in map uv). The shadow pass clips a
  // packed view's casters to its triangle, so views sharing a layer do not overwrite each other.
  int layer = -1;
  int packedTriangle = -1;
  // Views in an atlas (several faces of one layer, each in a rectangle sized by its need): the
  // rectangle of the layer this view is drawn into, x, y, width, height in texels; the shadow
  // pass scissors and clears it alone (viewProj already maps the view into it). Zero: the whole
  // layer.
  glm::ivec4 atlasRect{0};
};

// A paraboloid view (Brabec, Annen & Seidel 2002) maps the direction d from the light, in its
// view frame (the hemisphere's axis is -z), to d.xy / (1 - d.z): the hemisphere fills the unit
// disk, scaled by 1 / kParaboloidWindow so filter taps just past the rim read drawn texels. Its
// depth is the radial distance over [nearPlane, farPlane] (layouts/dual_paraboloid.glsl).
inline constexpr float kParaboloidWindow = 1.05f;

// The whole hemisphere's image of a unit direction d in a paraboloid view's frame (axis -z):
// d.xy / (1 - d.z) / kParaboloidWindow, before a fitted window zooms it.
inline glm::vec2 paraboloidDiskImage(const glm::vec3& d) {
  return glm::vec2(d) / std::max(1.0f - d.z, 1e-4f) / kParaboloidWindow;
}

// δ above this: the log warp is the identity to float precision (LightView::logDelta).
inline constexpr float kNoWarpDelta = 1e6f;

// The warp of a map's normalized distance t from its near side (t in [0, 1] inside the map;
// outside it is extended, and clamped far before the logarithm's pole).
float logWarp(float t, float delta);
// A world point's clip position in a light view, its log warp applied (w = 1 for orthographic
// views; other views as viewProj gives them).
glm::vec4 lightViewClip(const LightView& view, const glm::vec3& world);

constexpr int kMaxLightViews = 8;

// What a layout computed for one frame: 1..kMaxLightViews views, one shadow-map layer each
// (or several views packed into one layer, LightView::layer), all of `size` x `size` texels. The renderer uploads the
// views as one uniform block (shaders/common/light_views.glsl).
struct LightSpace {
  std::vector<LightView> views{LightView{}};
  int size = 1024;  // texels per side of every layer
  // placeInAtlasRegion's scale and offset (x, y) of the layer's image in the atlas's [-1, 1]
  // square: a packed view's triangle is tested in its layer's own square (light_views.glsl).
  glm::vec3 atlasPlacement{1.0f, 0.0f, 0.0f};
  const LightView& primary() const { return views.front(); }
  bool perspective() const;  // any view perspective: stored depth is written per fragment
  static LightSpace single(const LightView& view, int size) { return LightSpace{{view}, size}; }
  int layerOf(size_t view) const;  // the layer view `view` is drawn into (LightView::layer)
  int layerCount() const;          // layers the map needs: one per view unless views are packed
  bool packed() const;             // some view owns a triangle of a shared layer
  bool sharesLayers() const;       // some layer holds several views (packed or in an atlas)
};

// The map's [-1, 1] square scaled to `side` texels and centred on `rect` (x, y, width, height in
// texels) of a layer of layerSize² texels: what follows a view's projection to draw it into a
// rectangle of a shared layer (an atlas face's square, a light's region of one atlas).
glm::mat4 squareOntoRect(const glm::ivec4& rect, float side, int layerSize);

// A light's one-layer space moved into `region` (x, y, side, side in texels) of an atlas layer of
// atlasSize² shared with other lights (lights.one_atlas): every view's projection followed by the
// scale and offset that put its layer's image inside the region, its atlasRect (or, for a view
// of the whole layer, the region) and receiver hull moved with it, and `size` the atlas's. Texel
// sizes are unchanged; a view packed into a triangle gets the whole region (its clip keeps to its
// triangle), another view of several without an atlasRect keeps none (the renderer draws no such
// view of a shared layer). Only a single layer of the region's side, of matrix projections:
// otherwise false, unchanged.
bool placeInAtlasRegion(LightSpace& space, const glm::ivec4& region, int atlasSize);

// What the visible pixels of an earlier frame covered (sample-distribution fitting, SDSM):
// camera view depth and position in the light's fixed basis (lightViewMatrix), min and max.
struct VisibleBounds {
  bool valid = false;
  float depthMin = 0, depthMax = 0;
  glm::vec3 lightMin{0.0f}, lightMax{0.0f};  // x, y and light-view distance
};

struct LayoutInput {
  const Scene* scene = nullptr;
  double time = 0.0;
  glm::mat4 cameraView{1.0f};
  glm::mat4 cameraProj{1.0f};
  const ParamSet* params = nullptr;
  LayoutJitter jitter;
  VisibleBounds visible;  // set by SdsmState when fit.sdsm is on and bounds have arrived
  // Unique per Renderer::setScene call over all renderers (0: unknown). What a layout derives
  // from the scene's geometry alone may be cached under it (a scene's address may be reused).
  uint64_t sceneGeneration = 0;
  // The light these views are for: one of the scene's shadowed lights (null: scene->light).
  const Light* light = nullptr;
  // How far the representation's lookups read past a receiver's texel (Representation::
  // filterReachTexels): what a view drawn only up to its window's edge would lose to the clamp.
  float filterReachTexels = 0.0f;
  const Light& shadowedLight() const { return light ? *light : scene->light; }
};

}  // namespace sl
