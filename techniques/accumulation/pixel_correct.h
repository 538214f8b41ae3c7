// Pixel-correct shadow maps with temporal reprojection and shadow-test confidence
// (Scherzer, Jeschke, Wimmer, EGSR 2007). A screen-space history buffer s(n) is updated with
// s(n) = w f(n) + (1 - w) s(n-1), w = conf^m (eq. 2, 5, 6), while the layout's projection
// window is jittered (Halton translation + in-plane rotation) so that every frame rasterizes
// the shadow map differently and some test lands close to a texel centre for every pixel.
#pragma once

#include "part/part.h"
#include "gl/gl_util.h"

#include <array>
#include <memory>

namespace sl {

// Radical inverse of index in the given base (Halton sequence), in [0,1).
float halton(int index, int base);

// The jitter of frame `index` for the given parameters (what the state returns; public for tests).
LayoutJitter pixelCorrectJitter(const ParamSet& params, int index);

// Exponent m for the next frame: fixed pc.m, or adaptive (pc.m_moving while the camera moves or
// there is no history, then + pc.m_step per still frame up to pc.m).
float pixelCorrectNextExponent(const ParamSet& params, float previous, bool moving, bool haveHistory);

class PixelCorrectState : public AccumulationState {
 public:
  LayoutJitter jitter(const ParamSet& params, bool cameraMoved) const override;
  void reset() override;
  // One scene pass runs the test, the update and the shading (no separate visibility pass).
  AccumulationOutput addPasses(FrameGraph& graph, const AccumulationContext& ctx) override;
  std::vector<std::string> views() const override { return {"confidence", "history", "disocclusion"}; }
  std::string status() const override;

  float exponent() const { return m_; }
  int framesSinceReset() const { return frames_; }
  bool hasHistory() const { return hasHistory_; }

 private:
  // What one frame's update pass changes, committed when the pass runs (a culled pass changes
  // nothing).
  struct FrameUpdate {
    int write = 0;
    float m = 0.0f;
    bool adaptive = true, keepBest = false, showingTest = false, advanceJitter = true;
  };
  void commit(const FrameUpdate& u);
  void ensureHistory(int w, int h, GLenum format);
  Framebuffer* updateFramebuffer(int write, const AccumulationContext& ctx, Texture2D* rawTarget);
  std::array<std::unique_ptr<Texture2D>, 2> history_;  // r = s, g = linear view depth (0 = none), b = W
  std::array<Framebuffer, 2> fbo_;                     // colour, history[i] (= shown), raw if wanted
  const Texture2D* fboRaw_[2] = {nullptr, nullptr};
  const Texture2D* fboColor_[2] = {nullptr, nullptr};
  int current_ = 0;  // history_[current_] holds the latest frame
  bool hasHistory_ = false;
  float m_ = 0.0f;
  int frames_ = 0;       // frames since the last reset
  int jitterIndex_ = 0;  // Halton index of the next frame
  bool adaptive_ = true;
  bool keepBest_ = false;     // for the status line
  bool showingTest_ = false;  // this frame shows the plain test (pc.while_moving=test, camera moving)
};

}  // namespace sl
