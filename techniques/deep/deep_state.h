// Per-viewport state of the deep shadow map (Lokovic & Veach 2000): an ordinary depth map for
// the opaque casters plus, per light texel, a transmittance function of light depth for the
// semi-transparent ones (hair fragments and volumes), compressed to a fixed number of
// piecewise-linear nodes. In a scene without semi-transparent casters it is the depth map alone:
// no deep pass, no define, the same shaders as depth-nearest.
#pragma once

#include "deep/deep_fit.h"
#include "part/depth_map_state.h"
#include "gl/gl_util.h"
#include "gl/readback_ring.h"
#include "part/part.h"

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace sl {

class DeepState : public RepresentationState {
 public:
  DeepState() : opaque_(false) {}
  ~DeepState() override;
  void setScene(const Scene& scene, const Light& light) override;
  void configure(const ParamSet& params) override;
  void prepare(int size, int layers, int views) override;
  void beginShadowLayer(int layer) override { opaque_.beginShadowLayer(layer); }
  void continueShadowLayer(int layer) override { opaque_.continueShadowLayer(layer); }
  std::string addPasses(FrameGraph& graph, const PartContext& ctx) override;
  const Texture2D* depthTexture() const override { return opaque_.depthTexture(); }
  std::string defines() const override;
  void bind(const Program& p, TextureUnits& units) const override;
  std::vector<std::string> views() const override;
  std::string status() const override;
  long long texels() const override;
  VisibilityCurve visibilityCurve(const CurveQuery& query) const override;

  bool active() const { return active_; }
  // Of the last frame (waiting for its counters): fragments that did not fit their texel's list,
  // texels whose function needed a larger tolerance than deep.tolerance to fit deep.nodes nodes.
  unsigned overflowFragments() const { return overflow(0); }
  unsigned relaxedTexels() const { return overflow(1); }
  // Light-image samples per deep texel, as the last frame's fragment pass rasterized them.
  int samples() const { return std::max(static_cast<int>(overflow(2)), 1); }
  const Texture2D& nodes() const { return nodes_; }    // RG32F array: layer view*N + k = (depth, T)
  const Texture2D& counts() const { return counts_; }  // R32F array: nodes used per texel
  // The part of light view `layer` the deep map covers this frame (deep_fit.h).
  const DeepWindow& window(int layer) const { return windows_.at(static_cast<size_t>(layer)); }

 private:
  void releaseBuffers();
  void setSampleCount();
  void fragmentsPass(const PartContext& ctx);
  void compressPass(const PartContext& ctx);
  void fitWindows(const PartContext& ctx);
  // DeepOverflow (dropped fragments, relaxed texels, samples) of the last frame (waiting for its
  // copy).
  unsigned overflow(int index) const;

  DepthMapState opaque_;
  bool active_ = false;
  int nodeCount_ = 8, maxFragments_ = 32, deepSize_ = 512, steps_ = 48, views_ = 1;
  // deep.samples as asked, and as the framebuffer without attachments actually rasterizes.
  int samplesAsked_ = 1;
  Texture2D nodes_, counts_;
  std::array<DeepWindow, kMaxLightViews> windows_{};
  GLuint fragmentCounts_ = 0, fragments_ = 0, overflowBuffer_ = 0, emptyFbo_ = 0;
  size_t bufferTexels_ = 0, bufferFragments_ = 0;
  static constexpr size_t kOverflowBytes = 3 * sizeof(unsigned);  // DeepOverflow
  // The counters copied each frame and read when they have arrived: the status line makes the
  // CPU wait for no frame (mutable: reading an arrived copy changes nothing the state shows).
  mutable std::unique_ptr<ReadbackRing> overflowCopies_;
};

}  // namespace sl
