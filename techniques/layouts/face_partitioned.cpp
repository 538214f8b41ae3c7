// Face partitioning (Lloyd, Tuft, Yoon, Manocha 2006, "Warping and partitioning for low error
// shadow maps", EGSR; the survey's "split the frustum by faces" slide): when the light comes from
// behind or in front of the viewer, one warp along the view direction cannot help (the view
// direction is seen end-on from the light), but each side face of the frustum is seen from the
// side. The frustum is split by its two diagonal planes into four pyramids, one per side face;
// each gets its own LiSPSM map warped along its face (from the eye toward the face's far edge),
// a layer of the array each. With faces.depth_splits = 2 each pyramid is also cut in depth (the
// paper's combination of face and z-partitioning): eight maps, a pixel picks face and slice.
#include "layouts/face_partitioned.h"

#include "gl/shader_library.h"
#include "layouts/cascade_fit.h"
#include "layouts/cascaded.h"
#include "part/light_frame.h"
#include "layouts/lispsm.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace sl {

namespace {

constexpr float kSliceLambda = 0.5f;  // halfway between logarithmic and uniform: the near slice keeps some ground

// The four pyramids: right (x >= |y|), left, top, bottom in camera clip space. Each is given as
// the 8 corners of a frustum (index x + 2y + 4z) whose x = 0 edge collapses onto the view axis,
// so clipCornersToBox clips it to the scene like the focused receivers.
std::vector<glm::vec3> pyramidCorners(const glm::mat4& view, const glm::mat4& proj, int face) {
  const glm::mat4 inv = glm::inverse(proj * view);
  auto at = [&](float x, float y, float z) {
    glm::vec4 p = inv * glm::vec4(x, y, z, 1.0f);
    return glm::vec3(p) / p.w;
  };
  static const float edge[4][2][2] = {{{1, -1}, {1, 1}}, {{-1, -1}, {-1, 1}}, {{-1, 1}, {1, 1}}, {{-1, -1}, {1, -1}}};
  std::vector<glm::vec3> c(8);
  for (int z = 0; z < 2; ++z) {
    const float nz = z ? 1.0f : -1.0f;
    c[4 * z + 0] = c[4 * z + 2] = at(0, 0, nz);
    c[4 * z + 1] = at(edge[face][0][0], edge[face][0][1], nz);
    c[4 * z + 3] = at(edge[face][1][0], edge[face][1][1], nz);
  }
  return c;
}

class FacePartitionedState : public LayoutState {
 public:
  using LayoutState::LayoutState;
  LightSpace compute(const LayoutInput& in) override {
    cameraViewProj_ = in.cameraProj * in.cameraView;
    return layout_.compute(in);
  }
  void bind(const Program& p, TextureUnits&) const override { p.set("u_cameraViewProj", cameraViewProj_); }
  // The cascades view colours each pixel by the map it reads: here the face (and slice).
  std::vector<std::string> views() const override { return {"cascades"}; }
  std::vector<std::string> addPasses(FrameGraph& graph, const PartContext& ctx) override {
    addCascadesViewPass(graph, ctx);
    return {};
  }

 private:
  glm::mat4 cameraViewProj_{1.0f};
};

class FacePartitionedLayout : public Layout {
 public:
  std::string id() const override { return "face-partitioned"; }
  std::string help() const override {
    return "face partitioning (Lloyd et al. 2006): the frustum split by its diagonal planes into one pyramid per side "
           "face, each LiSPSM-warped along its face";
  }
  std::string glslModule() const override { return "layouts/face_partitioned.glsl"; }
  std::vector<ParamDecl> params() const override {
    std::vector<ParamDecl> decls = lispsmParams();
    decls.push_back({.key = "faces.depth_splits",
                     .type = ParamType::Int,
                     .min = 1,
                     .max = 2,
                     .defaultValue = 1,
                     .help = "slices in depth of every face's pyramid (2: face and z-partitioning combined, eight "
                             "maps; the split at the practical scheme's depth, lambda 0.5)"});
    return decls;
  }
  std::unique_ptr<LayoutState> createState() const override { return std::make_unique<FacePartitionedState>(*this); }
  LightSpace compute(const LayoutInput& in) const override {
    const Bounds bounds = in.scene->boundsAt(in.time);
    const auto casters = boxCorners(bounds);
    const int size = in.params->i("shadowmap.size");
    const glm::mat4 inv = glm::inverse(in.cameraView);
    const glm::vec3 eye(inv[3]), up(inv[1]);
    LightSpace space;
    space.size = size;
    space.views.clear();
    const CameraFrustum cam = cameraFrustum(in.cameraView, in.cameraProj);
    // The slices share out the view depths where the scene is (frustum ∩ bounds), not the near
    // plane's: the ground of a standing viewer starts metres away.
    float zMin = 1e30f, zMax = 0.0f;
    for (const auto& p : clipFrustumToBox(in.cameraView, in.cameraProj, bounds)) {
      const float z = glm::dot(p - cam.eye, cam.forward);
      zMin = std::min(zMin, z), zMax = std::max(zMax, z);
    }
    if (zMin > zMax) zMin = cam.zNear, zMax = cam.zFar;
    zMin = std::max(zMin, cam.zNear);
    const int slices = in.params->i("faces.depth_splits");
    const std::vector<float> splits =
        cascadeSplits(slices, SplitScheme::Practical, kSliceLambda, zMin, std::max(zMax, zMin * 1.01f));
    for (int view = 0; view < 4 * slices; ++view) {
      const int face = view % 4, slice = view / 4;
      // The first slice starts at the near plane and the last reaches the far plane: no pixel is
      // left without a map.
      const float a = slice == 0 ? cam.zNear : splits[size_t(slice)];
      const float b = slice + 1 == slices ? cam.zFar : splits[size_t(slice) + 1];
      const glm::mat4 proj = slices == 1 ? in.cameraProj : sliceProjection(in.cameraProj, a, b);
      const auto corners = pyramidCorners(in.cameraView, proj, face);
      auto receivers = clipCornersToBox(corners, bounds);
      if (receivers.empty()) receivers = corners;  // this pyramid sees no scene: any small map will do
      // The warp runs along the face: from the eye toward the middle of the face's far edge.
      glm::vec3 dir = 0.5f * (corners[5] + corners[7]) - eye;
      if (glm::length(dir) < 1e-6f) dir = -glm::vec3(inv[2]);
      const glm::vec3 d = glm::normalize(dir);
      const glm::mat4 faceView = glm::lookAt(eye, eye + d, std::abs(glm::dot(d, up)) > 0.99f ? glm::vec3(inv[0]) : up);
      LightView v = lispsmView(layoutLight(in), faceView, receivers, casters, lispsmN(*in.params), size,
                               in.params->b("layout.snap"), in.jitter);
      v.splitNear = a;
      v.splitFar = slice + 1 == slices ? 1e30f : b;  // the GLSL module picks the slice by view depth
      space.views.push_back(v);
    }
    return space;
  }
};

}  // namespace

void registerFacePartitionedLayouts(std::vector<std::unique_ptr<Layout>>& out) {
  out.push_back(std::make_unique<FacePartitionedLayout>());
}

}  // namespace sl
