// The shadow targets of the depth representations: one 32-bit depth texture array, a layer per
// light view, sampled raw (nearest) or through hardware comparison (sampler2DArrayShadow).
#pragma once

#include "gl/gl_util.h"
#include "part/part.h"

#include <vector>

namespace sl {

class DepthMapState : public RepresentationState {
 public:
  // shareable: the map may be drawn into a layer shared by several lights (shareDepthLayer); a
  // state whose own passes read its map as a whole layer leaves it false.
  explicit DepthMapState(bool compare, bool shareable = false);
  ~DepthMapState() override;
  void prepare(int size, int layers, int views) override;
  void beginShadowLayer(int layer) override;
  // Keeps the content: no pass of ours reads the whole layer.
  bool keepsLayers() const override { return true; }
  void bindShadowLayer(int layer) override;
  void continueShadowLayer(int layer) override { bindShadowLayer(layer); }
  void bind(const Program& p, TextureUnits& units) const override;
  bool shareDepthLayer(const SharedDepthLayer* shared) override;
  bool canShareDepthLayer() const override { return shareable_; }
  const Texture2D* depthTexture() const override { return shared_ ? shared_->depth : &depth_; }
  long long texels() const override;
  // Remembers whether the scene has an area light, which a hard depth test ignores (status).
  std::string addPasses(FrameGraph& graph, const PartContext& ctx) override;
  std::string status() const override { return status_; }

 private:
  void createSampler();
  bool compare_;
  bool shareable_;
  const SharedDepthLayer* shared_ = nullptr;  // this frame's shared layer, or null: depth_
  GLuint sampler_ = 0;
  Texture2D depth_;
  std::vector<Framebuffer> layers_;
  std::string status_;
};

}  // namespace sl
