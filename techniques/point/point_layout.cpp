// The point family's layouts, one class over their views: the cube and the tetrahedron (face
// sets, light_faces.cpp) and the dual paraboloid (dual_paraboloid.cpp).
#include "point/point_layout.h"

#include "part/light_frame.h"
#include "point/directions_view.h"
#include "point/dual_paraboloid.h"

#include <string>

namespace sl {
namespace {

// The views under a point light; under any other light one focused map (every view needed).
FaceViews viewsOrFocused(const PointLayoutSpec& spec, const LayoutInput& in, bool& pointLight) {
  const Light light = sampledLight(in.shadowedLight(), in.jitter.lightSample);
  pointLight = light.type == Light::Type::Point;
  if (pointLight) return spec.views(light, in);
  FaceViews focused;
  focused.space = focusedMap(in, focusBody(in));
  focused.needed.assign(focused.space.views.size(), true);
  return focused;
}

// Remembers which views this frame needs: the shadow pass draws only those.
class PointLayoutState : public LayoutState {
 public:
  PointLayoutState(const Layout& layout, const PointLayoutSpec& spec) : LayoutState(layout), spec_(spec) {}
  LightSpace compute(const LayoutInput& in) override {
    bool pointLight = false;
    FaceViews v = viewsOrFocused(spec_, in, pointLight);
    needed_ = v.needed;
    status_ = pointLight ? spec_.id + ": " + std::to_string(v.neededCount()) + " of " +
                               std::to_string(v.needed.size()) + " " + spec_.unit + " drawn"
                         : spec_.id + ": the scene's light is not a point light; one focused map";
    return v.space;
  }
  void planShadowLayers(std::vector<ShadowLayerDraw>& layers, bool) override {
    for (size_t f = 0; f < layers.size() && f < needed_.size(); ++f)
      if (!needed_[f]) layers[f] = ShadowLayerDraw{.tiled = true, .tiles = {}};  // cleared, nothing drawn
  }
  std::string status() const override { return status_; }
  std::vector<std::string> views() const override { return {"directions"}; }
  void addPassesAfterShadow(FrameGraph& graph, const PartContext& ctx) override { addDirectionsViewPass(graph, ctx); }

 private:
  const PointLayoutSpec& spec_;
  std::vector<bool> needed_;
  std::string status_;
};

class PointLayout : public Layout {
 public:
  explicit PointLayout(PointLayoutSpec spec) : spec_(std::move(spec)) {}
  std::string id() const override { return spec_.id; }
  std::string help() const override { return spec_.help; }
  std::string glslModule() const override { return spec_.glslModule; }
  std::vector<ParamDecl> params() const override { return spec_.params; }
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
       .views = [](const Light& light, const LayoutInput& in) { return faceViews(cubeFaceSet(), light, in); }}));
  out.push_back(makePointLayout(
      {.id = "tetrahedron",
       .help = "point light: four faces of a tetrahedron (Liao 2010), one layer each, each fitted to what the camera "
               "sees through its triangle; faces with no visible receiver are not drawn",
       .glslModule = "layouts/light_faces.glsl",
       .unit = "faces",
       .params = {},
       .views = [](const Light& light, const LayoutInput& in) { return faceViews(tetrahedronFaceSet(), light, in); }}));
  out.push_back(makeDualParaboloidLayout());
}

}  // namespace sl
