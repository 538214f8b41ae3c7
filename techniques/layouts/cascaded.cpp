// Cascaded / parallel-split shadow maps (Zhang, Sun, Xu, Lun 2006 "Parallel-split shadow maps";
// Engel 2007 "Cascaded shadow maps", ShaderX5): the camera's depth range is split in 1..8 parts,
// each gets its own map of shadowmap.size² (a layer of the array), fitted to the split's bounding
// sphere and snapped to whole texels; pixels pick the split by their camera view depth and blend
// with the next one across a band before the border. Optionally each split is LiSPSM-warped
// (the survey's "z-partitioning and warping").
#include "layouts/cascaded.h"

#include "gl/shader_library.h"
#include "layouts/cascade_fit.h"
#include "part/light_frame.h"
#include "layouts/lispsm.h"
#include "layouts/sdsm.h"

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

// The camera depth range the splits cover: the camera's near plane to the farthest point of the
// scene (or the far plane). Both stay put while the camera turns, so do the splits and spheres.
std::pair<float, float> splitRange(const CameraFrustum& cam, const Bounds& bounds, const VisibleBounds& visible) {
  // Sample-distribution fitting: the splits go over the depths the pixels showed (with 1 %).
  if (visible.valid)
    return {std::max(cam.zNear, visible.depthMin * 0.99f),
            std::max(std::min(cam.zFar, visible.depthMax * 1.01f), cam.zNear * 1.01f)};
  float farthest = 0.0f;
  for (const auto& p : boxCorners(bounds)) farthest = std::max(farthest, glm::length(p - cam.eye));
  const float zFar = std::min(cam.zFar, farthest);
  return {cam.zNear, std::max(zFar, cam.zNear * 1.01f)};
}

// One split's light view: the bounding sphere fit (or a spot light's cropped cone, or a LiSPSM
// warp of the split's receivers).
LightView cascadeView(const LayoutInput& in, const CameraFrustum& cam, float a, float b,
                      const std::vector<glm::vec3>& casters) {
  const Light light = layoutLight(in);
  const int size = in.params->i("shadowmap.size");
  const bool warp = in.params->choice("cascades.warp") == "lispsm";
  if (light.type != Light::Type::Spot && !warp)
    return fitSphereOrthographic(lightViewMatrix(light, in.jitter.rotationRad), sliceBoundingSphere(cam, a, b), casters,
                                 size, in.params->b("layout.snap"), in.jitter);
  auto receivers = clipFrustumToBox(in.cameraView, sliceProjection(in.cameraProj, a, b), in.scene->boundsAt(in.time));
  if (receivers.empty()) receivers = frustumCorners(in.cameraView, sliceProjection(in.cameraProj, a, b));
  if (light.type == Light::Type::Spot)
    return fitPerspective(light, lightViewMatrix(light, in.jitter.rotationRad), receivers, casters, size, true,
                          in.params->b("layout.snap"), in.jitter);
  return lispsmView(light, in.cameraView, receivers, casters, lispsmN(*in.params), size, in.params->b("layout.snap"),
                    in.jitter);
}

class CascadedState : public SdsmState {
 public:
  using SdsmState::SdsmState;
  LightSpace compute(const LayoutInput& in) override {
    cameraView_ = in.cameraView;
    return SdsmState::compute(in);
  }
  // The GLSL module picks the split by the pixel's camera view depth.
  void bind(const Program& p, TextureUnits&) const override { p.set("u_cameraView", cameraView_); }
  std::vector<std::string> views() const override { return {"cascades"}; }
  std::vector<std::string> addPasses(FrameGraph& graph, const PartContext& ctx) override {
    addCascadesViewPass(graph, ctx);
    return SdsmState::addPasses(graph, ctx);
  }

 private:
  glm::mat4 cameraView_{1.0f};
};

class CascadedLayout : public Layout {
 public:
  std::string id() const override { return "cascaded"; }
  std::string help() const override {
    return "cascaded / parallel-split shadow maps (Zhang et al. 2006, Engel 2007): one snapped map per camera-depth "
           "split, blended across split borders";
  }
  std::string glslModule() const override { return "layouts/cascaded.glsl"; }
  std::vector<ParamDecl> params() const override;
  std::unique_ptr<LayoutState> createState() const override { return std::make_unique<CascadedState>(*this); }

  LightSpace compute(const LayoutInput& in) const override {
    const CameraFrustum cam = cameraFrustum(in.cameraView, in.cameraProj);
    const Bounds bounds = in.scene->boundsAt(in.time);
    const auto casters = boxCorners(bounds);
    const auto [zNear, zFar] = splitRange(cam, bounds, in.params->b("fit.sdsm") ? in.visible : VisibleBounds{});
    const int count = in.params->i("cascades.count");
    const auto scheme = static_cast<SplitScheme>(in.params->i("cascades.scheme"));
    const auto splits = cascadeSplits(count, scheme, in.params->f("cascades.lambda"), zNear, zFar);
    LightSpace space;
    space.size = in.params->i("shadowmap.size");
    space.views.clear();
    float band = 0.0f;  // the previous split's blend band: this split must cover it too
    for (int i = 0; i < count; ++i) {
      const float a = splits[i], b = splits[i + 1];
      LightView v = cascadeView(in, cam, std::max(a - band, zNear), b, casters);
      band = i + 1 < count ? in.params->f("cascades.blend") * (b - a) : 0.0f;
      v.splitNear = a;
      v.splitFar = i + 1 < count ? b : 1e30f;  // the last split takes everything beyond
      v.blendBand = band;
      space.views.push_back(v);
    }
    return space;
  }
};

std::vector<ParamDecl> CascadedLayout::params() const {
  std::vector<ParamDecl> decls = {
      {.key = "cascades.count",
       .type = ParamType::Int,
       .min = 1,
       .max = kMaxLightViews,
       .defaultValue = 4,
       .unit = "",
       .help = "number of camera-depth splits, each a map of shadowmap.size² texels"},
      {.key = "cascades.scheme",
       .type = ParamType::Enum,
       .defaultValue = 2,
       .help = "where the splits go: uniform in depth, logarithmic C_i = n (f/n)^(i/m), or the practical blend "
               "lambda * logarithmic + (1 - lambda) * uniform (Zhang et al. 2006)",
       .choices = {"uniform", "logarithmic", "practical"}},
      {.key = "cascades.lambda",
       .type = ParamType::Float,
       .min = 0,
       .max = 1,
       .defaultValue = 0.95,
       .unit = "",
       .help = "practical split scheme: weight of the logarithmic splits (1 = logarithmic, 0 = uniform); 0.95 "
               "measured best on terrain and columns together (techniques/layouts/README.md)"},
      {.key = "cascades.blend",
       .type = ParamType::Float,
       .min = 0,
       .max = 0.5,
       .defaultValue = 0.1,
       .unit = "of a split",
       .help = "band before each split border, as a fraction of that split's depth range, where the next split's "
               "test is blended in (hides the seam)"},
      {.key = "cascades.warp",
       .type = ParamType::Enum,
       .defaultValue = 0,
       .help = "warp inside each split: none (snapped orthographic maps) or LiSPSM with lispsm.n_scale (the survey's "
               "z-partitioning and warping; not snapped)",
       .choices = {"none", "lispsm"}},
  };
  // With cascades.warp=lispsm: the warp's n inside each split (that split's own z_n and n_opt).
  for (auto&& d : lispsmParams()) decls.push_back(d);
  for (auto&& d : sdsmParams()) decls.push_back(d);
  return decls;
}

}  // namespace

void registerCascadedLayouts(std::vector<std::unique_ptr<Layout>>& out) {
  out.push_back(std::make_unique<CascadedLayout>());
}

}  // namespace sl
