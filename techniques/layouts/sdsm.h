// Sample-distribution shadow maps (Lauritzen, Salvi, Lefohn 2011) as an option of `focused` and
// `cascaded` (fit.sdsm): a GPU min/max reduction of the visible pixels' depths and light-space
// positions before the shadow pass; its result, read back fit.sdsm_latency frames later (0 =
// this frame, waiting for the GPU), tightens the fit.
#pragma once

#include "part/part.h"

#include <array>
#include <memory>

namespace sl {

// Declarations of fit.sdsm and fit.sdsm_latency (shared by the layouts that offer it).
std::vector<ParamDecl> sdsmParams();

// World corners of the visible pixels' box in the light's fixed basis (a margin of 1 %).
std::vector<glm::vec3> visibleBoxCorners(const Light& light, const VisibleBounds& visible);

// Per-viewport state of a layout with the SDSM option: runs the reduction pass and hands the
// bounds to the layout's compute through LayoutInput::visible.
class SdsmState : public LayoutState {
 public:
  explicit SdsmState(const Layout& layout);
  ~SdsmState() override;
  void reset() override;
  LightSpace compute(const LayoutInput& in) override;
  std::vector<std::string> addPasses(FrameGraph& graph, const PartContext& ctx) override;
  void addPassesAfterShading(FrameGraph& graph, const PartContext& ctx, const AccumulationOutput& shaded) override;

 private:
  struct Gpu;
  // Dispatches the reduction into ring slot `slot`: over the G-buffer's positions, or with
  // `depth` over that depth target rebuilt to world positions with the camera of `ctx`.
  void reduce(const PartContext& ctx, int slot, const Texture2D* depth);
  std::unique_ptr<Gpu> gpu_;
  VisibleBounds latest_;  // the newest bounds read back
  LayoutInput lastInput_;
  int frames_ = 0;  // reductions dispatched since the last reset
  int slot_ = 0;    // this frame's ring slot
};

}  // namespace sl
