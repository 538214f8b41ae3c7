// The point family's layouts: the cube and the tetrahedron, one class over their face sets.
#include "part/light_frame.h"
#include "point/directions_view.h"
#include "point/light_faces.h"

#include <string>

namespace sl {
namespace {

// The faces under a point light; under any other light one focused map (every "face" needed).
FaceViews facesOrFocused(const FaceSet& set, const LayoutInput& in, bool& pointLight) {
  const Light light = sampledLight(in.scene->light, in.jitter.lightSample);
  pointLight = light.type == Light::Type::Point;
  if (pointLight) return faceViews(set, light, in);
  FaceViews focused;
  focused.space = focusedMap(in, focusBody(in));
  focused.needed.assign(focused.space.views.size(), true);
  return focused;
}

// Remembers which faces this frame needs: the shadow pass draws only those.
class FaceState : public LayoutState {
 public:
  FaceState(const Layout& layout, const FaceSet& set) : LayoutState(layout), set_(set) {}
  LightSpace compute(const LayoutInput& in) override {
    bool pointLight = false;
    FaceViews v = facesOrFocused(set_, in, pointLight);
    needed_ = v.needed;
    status_ = pointLight ? set_.name + ": " + std::to_string(v.neededCount()) + " of " +
                               std::to_string(set_.faces.size()) + " faces drawn"
                         : set_.name + ": the scene's light is not a point light; one focused map";
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
  const FaceSet& set_;
  std::vector<bool> needed_;
  std::string status_;
};

class FaceLayout : public Layout {
 public:
  FaceLayout(const FaceSet& set, std::string help) : set_(set), help_(std::move(help)) {}
  std::string id() const override { return set_.name; }
  std::string help() const override { return help_; }
  std::string glslModule() const override { return "layouts/light_faces.glsl"; }
  LightSpace compute(const LayoutInput& in) const override {
    bool pointLight = false;
    return facesOrFocused(set_, in, pointLight).space;
  }
  std::unique_ptr<LayoutState> createState() const override { return std::make_unique<FaceState>(*this, set_); }

 private:
  const FaceSet& set_;
  std::string help_;
};

}  // namespace

void registerPointLayouts(std::vector<std::unique_ptr<Layout>>& out) {
  out.push_back(std::make_unique<FaceLayout>(
      cubeFaceSet(),
      "point light: six 90-degree faces, each fitted to what the camera sees through it; faces with "
      "no visible receiver are not drawn (a directional or spot light gets the focused map)"));
  out.push_back(std::make_unique<FaceLayout>(
      tetrahedronFaceSet(),
      "point light: four faces of a tetrahedron (Liao 2010), one layer each, each fitted to what the camera sees "
      "through its triangle; faces with no visible receiver are not drawn"));
}

}  // namespace sl
