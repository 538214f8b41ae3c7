#include "point/cube_layout.h"

#include "part/light_frame.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <string>

namespace sl {

const std::array<CubeFace, 6>& cubeFaces() {
  static const std::array<CubeFace, 6> faces = {{{{1, 0, 0}, {0, -1, 0}},
                                                 {{-1, 0, 0}, {0, -1, 0}},
                                                 {{0, 1, 0}, {0, 0, 1}},
                                                 {{0, -1, 0}, {0, 0, -1}},
                                                 {{0, 0, 1}, {0, -1, 0}},
                                                 {{0, 0, -1}, {0, -1, 0}}}};
  return faces;
}

int CubeViews::neededCount() const { return static_cast<int>(std::count(needed.begin(), needed.end(), true)); }

namespace {

// The far plane: the farthest corner of the scene's bounds, or the light's range if nearer.
float cubeFar(const Light& light, const Bounds& bounds) {
  float far = 0.0f;
  for (const glm::vec3& c : boxCorners(bounds)) far = std::max(far, glm::length(c - light.position));
  if (light.range > 0.0f) far = std::min(far, light.range);
  return std::max(far * 1.01f, 1e-3f);
}

}  // namespace

CubeViews cubeViews(const Light& light, const LayoutInput& in) {
  const Bounds bounds = in.scene->boundsAt(in.time);
  const int size = in.params->i("shadowmap.size");
  const bool snap = in.params->b("layout.snap");
  const float far = cubeFar(light, bounds);
  // A near plane this close keeps casters touching the light in the map; stored depth is linear,
  // so it costs no precision.
  const float near = far * 1e-4f;
  std::vector<glm::vec4> seen = frustumPlanes(in.cameraProj * in.cameraView);
  const std::vector<glm::vec4> box = boxPlanes(bounds);
  seen.insert(seen.end(), box.begin(), box.end());
  Light faceLight = light;
  faceLight.type = Light::Type::Spot;
  faceLight.fovDeg = 90.0f;
  CubeViews out;
  out.space.views.clear();
  out.space.size = size;
  for (size_t f = 0; f < cubeFaces().size(); ++f) {
    const CubeFace& face = cubeFaces()[f];
    faceLight.direction = face.axis;
    glm::mat4 view = glm::lookAt(light.position, light.position + face.axis, face.up);
    if (in.jitter.rotationRad != 0.0f)
      view = glm::rotate(glm::mat4(1.0f), in.jitter.rotationRad, glm::vec3(0, 0, 1)) * view;
    const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, near, far);
    const std::vector<glm::vec3> pyramid = frustumCorners(view, proj);
    const std::vector<glm::vec3> receivers = clipCornersToPlanes(pyramid, seen);
    std::vector<glm::vec3> casters = clipCornersToPlanes(pyramid, box);
    out.needed[f] = !receivers.empty();
    if (casters.empty()) casters = pyramid;
    out.space.views.push_back(fitPerspective(faceLight, view, out.needed[f] ? receivers : pyramid, casters, size,
                                             out.needed[f], snap, in.jitter));
  }
  return out;
}

namespace {

// The cube under a point light; under any other light one focused map (every "face" needed).
CubeViews cubeOrFocused(const LayoutInput& in, bool& pointLight) {
  const Light light = sampledLight(in.scene->light, in.jitter.lightSample);
  pointLight = light.type == Light::Type::Point;
  if (pointLight) return cubeViews(light, in);
  CubeViews focused;
  focused.space = focusedMap(in, focusBody(in));
  focused.needed.fill(true);
  return focused;
}

// Remembers which faces this frame needs: the shadow pass draws only those.
class CubeState : public LayoutState {
 public:
  using LayoutState::LayoutState;
  LightSpace compute(const LayoutInput& in) override;
  void planShadowLayers(std::vector<ShadowLayerDraw>& layers, bool) override {
    for (size_t f = 0; f < layers.size() && f < needed_.size(); ++f)
      if (!needed_[f]) layers[f] = ShadowLayerDraw{.tiled = true, .tiles = {}};  // cleared, nothing drawn
  }
  std::string status() const override { return status_; }

 private:
  std::array<bool, 6> needed_{true, true, true, true, true, true};
  std::string status_;
};

class CubeLayout : public Layout {
 public:
  std::string id() const override { return "cube"; }
  std::string help() const override {
    return "point light: six 90-degree faces, each fitted to what the camera sees through it; faces with no "
           "visible receiver are not drawn (a directional or spot light gets the focused map)";
  }
  std::string glslModule() const override { return "layouts/cube.glsl"; }
  LightSpace compute(const LayoutInput& in) const override {
    bool pointLight = false;
    return cubeOrFocused(in, pointLight).space;
  }
  std::unique_ptr<LayoutState> createState() const override { return std::make_unique<CubeState>(*this); }
};

LightSpace CubeState::compute(const LayoutInput& in) {
  bool pointLight = false;
  CubeViews v = cubeOrFocused(in, pointLight);
  needed_ = v.needed;
  status_ = pointLight ? "cube: " + std::to_string(v.neededCount()) + " of 6 faces drawn"
                       : "cube: the scene's light is not a point light; one focused map";
  return v.space;
}

}  // namespace

void registerPointLayouts(std::vector<std::unique_ptr<Layout>>& out) { out.push_back(std::make_unique<CubeLayout>()); }

}  // namespace sl
