// A frame is a list of passes that declare the resources they read and write. Only passes
// whose outputs (transitively) reach a requested sink run: a debug view nobody shows, or a
// blur a technique does not need, costs nothing. No GL here, so it is tested without a GPU.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace sl {

struct Pass {
  std::string name;
  std::vector<std::string> reads;
  std::vector<std::string> writes;
  std::function<void()> execute;
};

struct PassTiming {
  std::string name;
  double ms = 0;
};

class FrameGraph {
 public:
  void add(Pass pass);
  void requestSink(const std::string& resource);     // something shown or read back needs it
  void importResource(const std::string& resource);  // lives across frames (e.g. last frame's history)
  // Names of the passes that will run, in submission order. Throws std::logic_error if a read
  // resource is produced by no pass earlier in the list or two passes share a name (wiring
  // mistakes, not user input). The renderer calls it on every frame in debug builds and tests.
  std::vector<std::string> compile() const;
  // Runs the culled list; `timer` wraps each pass (timing, debug groups).
  void execute(const std::function<void(const Pass&, const std::function<void()>&)>& wrapper) const;
  void clear();
  const std::vector<Pass>& passes() const { return passes_; }

 private:
  std::vector<bool> liveMask() const;
  std::vector<Pass> passes_;
  std::vector<std::string> sinks_;
  std::vector<std::string> imports_;
};

}  // namespace sl
