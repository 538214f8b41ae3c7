// Uniform and focused layouts: one light matrix each, sharing the single-matrix GLSL module.
#include "layouts/layouts.h"

#include "part/light_frame.h"
#include "layouts/sdsm.h"

namespace sl {

namespace {

class UniformLayout : public Layout {
 public:
  std::string id() const override { return "uniform"; }
  std::string help() const override {
    return "one shadow map over the whole scene's bounds (Williams 1978): simple, wasteful when the view is small";
  }
  std::string glslModule() const override { return "layouts/single_matrix.glsl"; }
  LightSpace compute(const LayoutInput& in) const override {
    const Light light = layoutLight(in);
    glm::mat4 view = lightViewMatrix(light, in.jitter.rotationRad);
    auto corners = boxCorners(in.scene->boundsAt(in.time));
    int size = in.params->i("shadowmap.size");
    bool snap = in.params->b("layout.snap");
    if (light.type == Light::Type::Spot)
      return LightSpace::single(fitPerspective(light, view, corners, corners, size, false, snap, in.jitter), size);
    return LightSpace::single(fitOrthographic(view, corners, corners, size, snap, in.jitter), size);
  }
};

// Brabec, Annen, Seidel 2002, "Practical shadow mapping": the light frustum covers only the
// visible receivers (view frustum ∩ scene bounds); casters are included by pulling the near
// plane toward the light up to the scene's bounds.
class FocusedLayout : public Layout {
 public:
  std::string id() const override { return "focused"; }
  std::string help() const override {
    return "light frustum fitted to view frustum ∩ scene, casters extended toward the light (Brabec et al. 2002)";
  }
  std::string glslModule() const override { return "layouts/single_matrix.glsl"; }
  std::vector<ParamDecl> params() const override { return sdsmParams(); }
  std::unique_ptr<LayoutState> createState() const override { return std::make_unique<SdsmState>(*this); }
  LightSpace compute(const LayoutInput& in) const override {
    const Light light = layoutLight(in);
    Bounds bounds = in.scene->boundsAt(in.time);
    glm::mat4 view = lightViewMatrix(light, in.jitter.rotationRad);
    auto casters = boxCorners(bounds);
    auto receivers = clipFrustumToBox(in.cameraView, in.cameraProj, bounds);
    if (receivers.empty()) receivers = casters;  // looking away from the scene: nothing to focus on
    // Sample-distribution fitting: only what the pixels showed (light-space box, fixed basis).
    if (in.params->b("fit.sdsm") && in.visible.valid && light.type != Light::Type::Spot)
      receivers = visibleBoxCorners(light, in.visible);
    int size = in.params->i("shadowmap.size");
    bool snap = in.params->b("layout.snap");
    LightView fitted = light.type == Light::Type::Spot
                           ? fitPerspective(light, view, receivers, casters, size, true, snap, in.jitter)
                           : fitOrthographic(view, receivers, casters, size, snap, in.jitter);
    fitted.receiverHull = receiverHullInMap(fitted, receivers);
    return LightSpace::single(fitted, size);
  }
};

}  // namespace

void registerBasicLayouts(std::vector<std::unique_ptr<Layout>>& out) {
  out.push_back(std::make_unique<UniformLayout>());
  out.push_back(std::make_unique<FocusedLayout>());
}

}  // namespace sl
