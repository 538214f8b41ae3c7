// Shadow silhouette maps (Sen, Cammarano and Hanrahan 2003): beside the depth map (a layer per
// light view) a silhouette map of the same size, offset by half a texel so that its texel
// corners are the depth samples, that keeps one point of a silhouette edge per texel in
// texel-local coordinates (RG16F: 1/2048 of a texel is finer than any edge needs; half the
// bytes of RG32F to clear and read on a software rasterizer; -1 where no edge passes). After the shadow pass the
// light's silhouette edges (CPU, from mesh adjacency) are drawn into it: a geometry shader widens each edge to a quad
// of one texel on every side (conservative), the fragment shader clips the edge to its texel and stores the clipped
// part's midpoint.
#pragma once

#include "part/depth_map_state.h"
#include "gl/gl_util.h"
#include "reconstruction/silhouette_edges.h"
#include "part/part.h"

#include <vector>

namespace sl {

class SilhouetteMapState : public RepresentationState {
 public:
  SilhouetteMapState() : depth_(false) {}
  ~SilhouetteMapState() override;
  void prepare(int size, int layers, int views) override;
  void beginShadowLayer(int layer) override { depth_.beginShadowLayer(layer); }
  void continueShadowLayer(int layer) override { depth_.continueShadowLayer(layer); }
  std::string addPasses(FrameGraph& graph, const PartContext& ctx) override;
  void bind(const Program& p, TextureUnits& units) const override;
  std::vector<std::string> views() const override { return {"silhouette-points"}; }
  std::string status() const override;
  const Texture2D* depthTexture() const override { return depth_.depthTexture(); }
  long long texels() const override { return 2 * depth_.texels(); }  // depth + one point per texel

  // Draws the silhouette edges into the silhouette map now (the frame graph's pass).
  void drawSilhouettes(const PartContext& ctx);
  const Texture2D& silhouetteMap() const { return points_; }
  size_t segmentCount() const { return segments_; }

 private:
  void upload(const std::vector<glm::vec3>& segments);
  DepthMapState depth_;
  Texture2D points_;
  std::vector<Framebuffer> fbos_;
  SilhouetteEdges edges_;
  GLuint vao_ = 0, vbo_ = 0;
  size_t segments_ = 0;
};

}  // namespace sl
