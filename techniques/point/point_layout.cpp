// The point family's layouts, one class over their views: the cube and the tetrahedron (face
// sets, light_faces.cpp) and the dual paraboloid (dual_paraboloid.cpp).
#include "point/point_layout.h"

#include "gl/shader_library.h"
#include "part/contexts.h"
#include "part/frame_graph.h"
#include "part/light_frame.h"
#include "point/directions_view.h"
#include "point/dual_paraboloid.h"
#include "point/face_cache.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

namespace sl {
namespace {

// The views under a point light; under any other light one focused map (every view needed).
FaceViews viewsOrFocused(const PointLayoutSpec& spec, const LayoutInput& in, bool& pointLight,
                         const std::vector<ViewPixelBounds>* seen = nullptr, AtlasHold* hold = nullptr) {
  const Light light = sampledLight(in.shadowedLight(), in.jitter.lightSample);
  pointLight = light.type == Light::Type::Point;
  if (pointLight) return spec.views(light, in, seen, hold);
  FaceViews focused;
  focused.space = focusedMap(in, focusBody(in));
  focused.needed.assign(focused.space.views.size(), true);
  return focused;
}

// What every point layout declares: whether faces are kept between frames (face_cache.h).
ParamDecl keepFacesParam() {
  return {.key = "point.keep_faces",
          .type = ParamType::Bool,
          .defaultValue = 1,
          .help =
              "keep a face's layer from an earlier frame while its view, the technique's values and shaders and "
              "the casters in its frustum are unchanged (depth representations, which keep their layers): a "
              "still camera redraws no face, an object moving under one face redraws that face"};
}

// The parameter values and the shader builds: a change redraws every face.
uint64_t techniqueStamp(const ParamSet& params, const ShaderLibrary* shaders) {
  uint64_t h = 1469598103934665603ull;
  auto mix = [&h](uint64_t v) { h = (h ^ v) * 1099511628211ull; };
  for (const ParamDecl& d : params.decls()) {
    mix(std::hash<std::string>{}(d.key));
    mix(std::hash<double>{}(params.get(d.key)));
  }
  mix(shaders ? static_cast<uint64_t>(shaders->buildCount()) : 0);
  return h;
}

// Remembers which views this frame needs and which it may keep: the shadow pass draws the rest.
class PointLayoutState : public LayoutState {
 public:
  PointLayoutState(const Layout& layout, const PointLayoutSpec& spec) : LayoutState(layout), spec_(spec) {}
  LightSpace compute(const LayoutInput& in) override {
    bool pointLight = false;
    FaceViews v = viewsOrFocused(spec_, in, pointLight, nullptr, &hold_);
    pointLight_ = pointLight;
    input_ = in;
    keepOn_ = in.params && in.params->has("point.keep_faces") && in.params->b("point.keep_faces");
    adopt(v);
    return v.space;
  }
  std::vector<std::string> addPasses(FrameGraph& graph, const PartContext& ctx) override {
    stamp_ = techniqueStamp(*ctx.params, ctx.shaders);
    for (FaceContent& c : content_) c.techniqueStamp = stamp_;
    if (!pointLight_ || !ctx.params->has("point.fit_visible") || !ctx.params->b("point.fit_visible")) return {};
    if (!reduction_) reduction_ = std::make_unique<ViewPixelReduction>();
    const std::string res = "point.pixel_bounds" + ctx.viewportTag;
    graph.add({"point.fit_visible" + ctx.viewportTag, {"gbuffer"}, {res}, [this, ctx] { refitToPixels(ctx); }});
    return {res};
  }
  void planShadowLayers(std::vector<ShadowLayerDraw>& layers, bool keepsLayers) override {
    std::vector<bool> kept(layers.size(), false);
    if (keepOn_ && keepsLayers && input_.scene) kept = cache_.keep(content_, needed_, *input_.scene, input_.time);
    // Faces packed into one layer or an atlas: drawing one clears the layer, so either every face
    // is kept or every needed one is drawn.
    if (space_.sharesLayers())
      for (size_t f = 0; f < needed_.size() && f < kept.size(); ++f)
        if (needed_[f] && !kept[f]) kept.assign(kept.size(), false);
    std::vector<bool> drawn(layers.size(), false);
    int keptCount = 0, neededCount = 0;
    for (size_t f = 0; f < layers.size() && f < needed_.size(); ++f) {
      neededCount += needed_[f] ? 1 : 0;
      keptCount += kept[f] ? 1 : 0;
      drawn[f] = needed_[f] && !kept[f];
      // Not drawn: tiles of nothing, so the layer is bound without being drawn (and kept as it
      // was when the representation keeps its layers).
      if (!drawn[f]) layers[f] = ShadowLayerDraw{.tiled = true, .tiles = {}};
    }
    cache_.record(content_, drawn, keepsLayers, input_.time);
    status_ = statusLine(neededCount, keptCount);
  }
  void reset() override {
    cache_.clear();
    hold_ = {};
  }
  // point.fit_visible: the views refitted to the bounds of the pixels that read them, measured in
  // the views compute() made (the same input gives the same rolled views), before the shadow pass.
  void refitToPixels(const PartContext& ctx) {
    const std::vector<ViewPixelBounds> seen = reduction_->reduce(ctx, space_, ctx.shadowedLight());
    if (seen.empty()) return;  // the pass did not run: the frustum fit stays
    bool pointLight = false;
    FaceViews v = viewsOrFocused(spec_, input_, pointLight, &seen, &hold_);
    adopt(v);
    ctx.replaceLightSpace(v.space);
  }
  std::string status() const override { return status_; }
  std::vector<std::string> views() const override { return {"directions"}; }
  void addPassesAfterShadow(FrameGraph& graph, const PartContext& ctx) override { addDirectionsViewPass(graph, ctx); }

 private:
  // This frame's views: what the shadow pass draws and the face cache compares.
  void adopt(const FaceViews& v) {
    needed_ = v.needed;
    space_ = v.space;
    content_.clear();
    for (const LightView& view : v.space.views)
      content_.push_back({.viewProj = view.viewProj,
                          .sceneGeneration = input_.sceneGeneration,
                          .techniqueStamp = stamp_,
                          .size = v.space.size,
                          .projective = view.projection == LightView::Projection::Matrix,
                          .paraboloidWindow = view.paraboloidWindow});
    status_ = statusLine(v.neededCount(), 0);
  }
  std::string statusLine(int needed, int kept) const {
    if (!pointLight_) return spec_.id + ": the scene's light is not a point light; one focused map";
    std::string s = spec_.id + ": " + std::to_string(needed) + " of " + std::to_string(needed_.size()) + " " +
                    spec_.unit + " drawn";
    if (kept > 0) s += ", " + std::to_string(kept) + " kept from an earlier frame";
    if (space_.packed())
      return s + " into triangles of one " + std::to_string(space_.size) + "² layer (Liao's packing, not fitted)";
    if (space_.sharesLayers()) s += atlasSides();
    return s + fittedZooms();
  }
  // An atlas: each drawn face's square and how much of the layer they fill.
  std::string atlasSides() const {
    std::string sides;
    double used = 0.0;
    for (size_t v = 0; v < space_.views.size() && v < needed_.size(); ++v) {
      const glm::ivec4& r = space_.views[v].atlasRect;
      if (!needed_[v] || r.z <= 0) continue;
      sides += (sides.empty() ? "" : "/") + std::to_string(r.z);
      used += double(r.z) * r.w;
    }
    char buf[96];
    std::snprintf(buf, sizeof buf, " in one %d² atlas (squares %s, %.0f %% of it)", space_.size, sides.c_str(),
                  100.0 * used / (double(space_.size) * space_.size));
    return buf;
  }
  // The drawn views' fitted windows as magnifications: of the whole disk for a paraboloid
  // (paraboloid.fit), of the square that holds the face's region for a face.
  std::string fittedZooms() const {
    std::string zooms;
    bool paraboloid = false;
    for (size_t v = 0; v < space_.views.size() && v < needed_.size(); ++v) {
      if (!needed_[v]) continue;
      const LightView& view = space_.views[v];
      paraboloid = view.projection == LightView::Projection::Paraboloid;
      const glm::vec2 zoom = paraboloid ? glm::vec2(view.paraboloidWindow.z, view.paraboloidWindow.w)
                                        : 2.0f / (view.windowMax - view.windowMin);
      char buf[48];
      if (std::abs(zoom.x - zoom.y) < 0.005f * zoom.x)
        std::snprintf(buf, sizeof buf, "%s%.2fx", zooms.empty() ? "" : ", ", zoom.x);
      else  // point.fit_visible fits a face's axes apart
        std::snprintf(buf, sizeof buf, "%s%.2fx%.2f", zooms.empty() ? "" : ", ", zoom.x, zoom.y);
      zooms += buf;
    }
    if (zooms.empty()) return "";
    return "; windows " + zooms + (paraboloid ? " the disk" : " the face");
  }
  const PointLayoutSpec& spec_;
  std::vector<bool> needed_;
  std::vector<FaceContent> content_;
  FaceCache cache_;
  AtlasHold hold_;
  LayoutInput input_;
  LightSpace space_;
  uint64_t stamp_ = 0;
  std::unique_ptr<ViewPixelReduction> reduction_;
  bool pointLight_ = false, keepOn_ = false;
  std::string status_;
};

class PointLayout : public Layout {
 public:
  explicit PointLayout(PointLayoutSpec spec) : spec_(std::move(spec)) {}
  std::string id() const override { return spec_.id; }
  std::string help() const override { return spec_.help; }
  std::string glslModule() const override { return spec_.glslModule; }
  std::vector<ParamDecl> params() const override {
    std::vector<ParamDecl> decls = spec_.params;
    decls.push_back(keepFacesParam());
    if (spec_.fitsToPixels) decls.push_back(fitVisibleParam());
    return decls;
  }
  LightSpace compute(const LayoutInput& in) const override {
    bool pointLight = false;
    return viewsOrFocused(spec_, in, pointLight).space;
  }
  std::unique_ptr<LayoutState> createState() const override { return std::make_unique<PointLayoutState>(*this, spec_); }

 private:
  PointLayoutSpec spec_;
};

}  // namespace

std::unique_ptr<Layout> makePointLayout(PointLayoutSpec spec) { return std::make_unique<PointLayout>(std::move(spec)); }

void registerPointLayouts(std::vector<std::unique_ptr<Layout>>& out) {
  out.push_back(makePointLayout(
      {.id = "cube",
       .help = "point light: six 90-degree faces, each fitted to what the camera sees through it; faces with no "
               "visible receiver are not drawn (a directional or spot light gets the focused map)",
       .glslModule = "layouts/light_faces.glsl",
       .unit = "faces",
       .params = {},
       .views = [](const Light& light, const LayoutInput& in, const std::vector<ViewPixelBounds>* seen, AtlasHold*) {
         FaceViews views = faceViews(cubeFaceSet(), light, in, seen);
         widenViews(views, in.filterReachTexels);
         return views;
       }}));
  out.push_back(makePointLayout(
      {.id = "cube-atlas",
       .help = "point light: the cube's six fitted faces in one atlas layer, each face's square sized by the part "
               "of the screen its visible receivers cover (beyond the papers); faces with no visible receiver get "
               "no square",
       .glslModule = "layouts/light_faces.glsl",
       .unit = "faces",
       .params = {{.key = "atlas.border",
                   .type = ParamType::Int,
                   .min = 0,
                   .max = 32,
                   .defaultValue = 4,
                   .unit = "texels",
                   .help = "texels drawn around each face's window inside its square of the atlas, so filter taps "
                           "past the window's edge read the same face rather than the next square"},
                  {.key = "atlas.hold",
                   .type = ParamType::Float,
                   .min = 1,
                   .max = 4,
                   .defaultValue = 1.5,
                   .unit = "x",
                   .help = "the squares are kept between frames while every face's screen footprint stays within "
                           "this factor of the one its square was sized for, so a moving camera does not change "
                           "the faces' texel sizes (and their edges) every frame; 1 sizes them anew every frame"}},
       .views = [](const Light& light, const LayoutInput& in, const std::vector<ViewPixelBounds>* seen,
                   AtlasHold* hold) {
         return atlasFaceViews(cubeFaceSet(), light, in, in.params->i("atlas.border"), seen, hold);
       }}));
  out.push_back(makePointLayout(
      {.id = "tetrahedron",
       .help = "point light: four faces of a tetrahedron (Liao 2010), one layer each, each fitted to what the camera "
               "sees through its triangle; faces with no visible receiver are not drawn",
       .glslModule = "layouts/light_faces.glsl",
       .unit = "faces",
       .params = {},
       .views = [](const Light& light, const LayoutInput& in, const std::vector<ViewPixelBounds>* seen, AtlasHold*) {
         // A face's square frustum already reaches well past its triangle: not widened (the
         // guard would cost a 256² face a quarter of its texels; seams.md, "Soft shadows").
         return faceViews(tetrahedronFaceSet(), light, in, seen);
       }}));
  out.push_back(makePointLayout(
      {.id = "tetrahedron-packed",
       .help = "point light: Liao's tetrahedron map, the four faces packed into one layer, each drawn into a "
               "triangle of it (the square split by its diagonals) with a guard band; not fitted to the view; "
               "faces with no visible receiver are not drawn",
       .glslModule = "layouts/light_faces.glsl",
       .unit = "faces",
       .params = {{.key = "tetrahedron.guard",
                   .type = ParamType::Float,
                   .min = 0,
                   .max = 64,
                   .defaultValue = 8,
                   .unit = "texels",
                   .help = "band inside each face's triangle of the layer that the face draws past its own "
                           "region, so filter taps reaching this far past a face edge read the same face (Liao's "
                           "guard band); the regions shrink by it"}},
       .fitsToPixels = false,
       .views = [](const Light& light, const LayoutInput& in, const std::vector<ViewPixelBounds>*, AtlasHold*) {
         return packedTetrahedronViews(light, in, static_cast<float>(in.params->get("tetrahedron.guard")));
       }}));
  out.push_back(makeDualParaboloidLayout());
}

}  // namespace sl
