#include "point/dual_paraboloid.h"

#include "part/light_frame.h"
#include "point/directions_view.h"
#include "point/light_faces.h"

#include <glm/gtc/matrix_transform.hpp>

#include <string>

namespace sl {

ParaboloidViews paraboloidViews(const Light& light, const LayoutInput& in) {
  const Bounds bounds = in.scene->boundsAt(in.time);
  const int size = in.params->i("shadowmap.size");
  const float far = pointLightFar(light, bounds);
  const float near = far * 1e-4f;  // as the cube's: linear depth, casters touching the light kept
  const std::vector<glm::vec3> box = boxCorners(bounds);
  const std::vector<glm::vec4> seen = frustumPlanes(in.cameraProj * in.cameraView);
  ParaboloidViews out;
  out.space.views.clear();
  out.space.size = size;
  const glm::vec3 axes[2] = {{0, -1, 0}, {0, 1, 0}}, ups[2] = {{0, 0, -1}, {0, 0, 1}};
  for (int h = 0; h < 2; ++h) {
    LightView v;
    v.view = glm::lookAt(light.position, light.position + axes[h], ups[h]);
    if (in.jitter.rotationRad != 0.0f)  // the disk turns about its axis; the hemisphere is the same
      v.view = glm::rotate(glm::mat4(1.0f), in.jitter.rotationRad, glm::vec3(0, 0, 1)) * v.view;
    // viewProj is not how casters reach this view (lightViewClip is); a 160-degree frustum around
    // the axis stands for it where a matrix is drawn (the light-space debug view's box).
    v.proj = glm::perspective(glm::radians(160.0f), 1.0f, near, far);
    v.viewProj = v.proj * v.view;
    v.perspective = true;
    v.nearPlane = near;
    v.farPlane = far;
    // Radians per texel are largest at the disk's centre: the image there moves by 1/2 per radian.
    v.texelWorldSize = 4.0f * kParaboloidWindow / size;
    v.projection = LightView::Projection::Paraboloid;
    out.space.views.push_back(v);
    // The lookup reads hemisphere 0 in front of the plane through the light across its axis, 1
    // behind it: a hemisphere is needed when a visible receiver lies on its side.
    std::vector<glm::vec4> planes = seen;
    planes.push_back(glm::vec4(axes[h], -glm::dot(axes[h], light.position)));
    out.needed[h] = !clipCornersToPlanes(box, planes).empty();
  }
  return out;
}

namespace {

ParaboloidViews paraboloidsOrFocused(const LayoutInput& in, bool& pointLight) {
  const Light light = sampledLight(in.scene->light, in.jitter.lightSample);
  pointLight = light.type == Light::Type::Point;
  if (pointLight) return paraboloidViews(light, in);
  ParaboloidViews focused;
  focused.space = focusedMap(in, focusBody(in));
  focused.needed.fill(true);
  return focused;
}

class ParaboloidState : public LayoutState {
 public:
  using LayoutState::LayoutState;
  LightSpace compute(const LayoutInput& in) override {
    bool pointLight = false;
    ParaboloidViews v = paraboloidsOrFocused(in, pointLight);
    needed_ = v.needed;
    status_ = pointLight
                  ? "dual-paraboloid: " + std::to_string(int(needed_[0]) + int(needed_[1])) + " of 2 hemispheres drawn"
                  : "dual-paraboloid: the scene's light is not a point light; one focused map";
    return v.space;
  }
  void planShadowLayers(std::vector<ShadowLayerDraw>& layers, bool) override {
    for (size_t h = 0; h < layers.size() && h < needed_.size(); ++h)
      if (!needed_[h]) layers[h] = ShadowLayerDraw{.tiled = true, .tiles = {}};  // cleared, nothing drawn
  }
  std::string status() const override { return status_; }
  std::vector<std::string> views() const override { return {"directions"}; }
  void addPassesAfterShadow(FrameGraph& graph, const PartContext& ctx) override { addDirectionsViewPass(graph, ctx); }

 private:
  std::array<bool, 2> needed_{true, true};
  std::string status_;
};

class DualParaboloidLayout : public Layout {
 public:
  std::string id() const override { return "dual-paraboloid"; }
  std::string help() const override {
    return "point light: two paraboloid views, one per hemisphere (Brabec, Annen & Seidel 2002); casters "
           "tessellated so their bent edges stay within paraboloid.max_error texels";
  }
  std::string glslModule() const override { return "layouts/dual_paraboloid.glsl"; }
  std::vector<ParamDecl> params() const override {
    return {{.key = "paraboloid.max_error",
             .type = ParamType::Float,
             .min = 0.05,
             .max = 16,
             .defaultValue = 0.5,
             .unit = "texels",
             .help = "largest distance between a tessellated caster edge and its true (circle-arc) image in a "
                     "paraboloid map; smaller = more tessellation",
             .logScale = true}};
  }
  LightSpace compute(const LayoutInput& in) const override {
    bool pointLight = false;
    return paraboloidsOrFocused(in, pointLight).space;
  }
  std::unique_ptr<LayoutState> createState() const override { return std::make_unique<ParaboloidState>(*this); }
};

}  // namespace

std::unique_ptr<Layout> makeDualParaboloidLayout() { return std::make_unique<DualParaboloidLayout>(); }

}  // namespace sl
