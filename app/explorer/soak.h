// `shadowlab --soak SECONDS`: drives the window unattended for reliability runs
// (scripts/soak.sh): every preset, scene, viewport count and debug view in turn, a shader
// broken and fixed again (only in a shader folder given with --shaders, never the source tree),
// GL errors checked every frame, resident memory reported at the end of each cycle through
// every preset and scene (the first cycle is the warm-up).
#pragma once

#include "explorer/explorer_state.h"
#include "gl/shader_library.h"

#include <string>
#include <vector>

namespace sl {

// Resident set size of this process in KiB (VmRSS of /proc/self/status), -1 if unknown.
long residentKiB();
// The same after malloc_trim: the memory held, without the free pages glibc keeps.
long heldKiB();

class SoakDriver {
 public:
  // shaderDir: the folder the explorer reads shaders from; the break/fix step only runs when it
  // is not the source tree's shaders/ (it writes to a file there).
  SoakDriver(double seconds, const std::string& shaderDir);
  // Before the frame's panels: the next action when the current one has had its frames.
  void beforeFrame(ExplorerState& state, Renderer& renderer, const ShaderLibrary& shaders, double now);
  // After the frame was drawn: GL errors, failed frames.
  void afterFrame(const ExplorerState& state);
  bool done() const { return done_; }
  // Prints the report (actions, frames, RSS at start and end, failures); the exit code.
  int finish();

  // RSS may grow by this much from the end of the warm-up before the run counts as leaking. The
  // warm-up is one visit of every preset and every scene: their shader programs, JIT code and
  // buffers are first made then, which took 260-280 MiB in 15 s (the bound used to apply from a
  // fixed share of the run, in whatever state the run was in, and that growth tripped it).
  // The samples are taken in the same baseline state, after malloc_trim, at the end of the
  // first cycle and of the last complete one; each cycle repeats the same states.
  static constexpr long kRssGrowthBoundKiB = 64 * 1024;

 private:
  void fail(const std::string& what);
  void nextAction(ExplorerState& state, Renderer& renderer);
  void breakShader();
  void fixShader();
  // Memory is sampled in one baseline state (first preset and scene, one viewport, no debug
  // views) after a few frames in it, at the end of every cycle.
  bool cycleCompleted(size_t sceneCount);  // every preset and every scene shown once more
  void goToBaseline(ExplorerState& state, Renderer& renderer);
  void takeSampleWhenSettled(const ShaderLibrary& shaders);

  double seconds_, start_ = -1, actionStart_ = 0;
  std::string brokenFile_, original_;
  bool canBreak_ = false, broken_ = false, done_ = false;
  int action_ = 0, framesInAction_ = 0, frames_ = 0;
  size_t presetIndex_ = 0, sceneIndex_ = 0, viewportStep_ = 0;
  long rssStart_ = -1, rssEnd_ = -1, rssPeak_ = -1;
  size_t cycles_ = 0, step_ = 0;
  static constexpr size_t kActionKinds = 5;
  bool sampling_ = false;
  int glErrorsAtStart_ = 0;
  std::vector<std::string> failures_;
};

}  // namespace sl
