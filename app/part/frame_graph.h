// A frame is a list of passes that declare the resources they read and write. Setup (add,
// createTexture, importResource, requestSink) has no side effects; compile() culls and checks the
// wiring; execute() runs what is live. Only passes whose outputs (transitively) reach a requested
// sink run: a debug view nobody shows, or a blur a technique does not need, costs nothing.
// Resources are named; a transient texture is declared with what it must be (TextureDesc) and
// the graph lends it for the live passes that use it, from first to last, through a
// TransientAllocator (part/transient_textures.h keeps a pool: targets are reused between frames
// and by passes whose lifetimes do not overlap). No GL here, so it is tested without a GPU.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace sl {

struct Pass {
  std::string name;
  std::vector<std::string> reads;
  std::vector<std::string> writes;
  std::function<void()> execute;
};

// What a transient texture must be: a 2D texture (layers 0) or an array of `layers`.
struct TextureDesc {
  unsigned format = 0;  // GL internal format
  int width = 0, height = 0;
  int layers = 0;
  int levels = 1;
  bool operator==(const TextureDesc&) const = default;
};

// Lends the graph its transient textures (opaque pointers here; a GL pool behind them).
class TransientAllocator {
 public:
  virtual ~TransientAllocator() = default;
  virtual void* acquire(const TextureDesc& desc, const std::string& name) = 0;
  virtual void release(void* texture) = 0;
};

struct PassTiming {
  std::string name;
  double ms = 0;
};

class FrameGraph {
 public:
  void add(Pass pass);
  void requestSink(const std::string& resource);      // something shown or read back needs it
  bool requested(const std::string& resource) const;  // requested as a sink so far (setup phase)
  // Whether anything that runs needs `resource`: a requested sink, or a read of a live pass. A
  // pass writing several resources asks it while it runs, to make only what is needed (the
  // G-buffer drawn as positions alone when nothing reads the rest).
  bool neededLive(const std::string& resource) const;
  void importResource(const std::string& resource);  // lives across frames (e.g. last frame's history)
  // A texture the graph owns for this frame: lent to the first live pass that uses it, taken back
  // after the last. Written before it is read, like any resource; contents do not survive.
  void createTexture(const std::string& resource, const TextureDesc& desc);
  // While a live pass that declared `resource` runs: the texture lent for it (what the allocator
  // returned); null otherwise.
  void* transient(const std::string& resource) const;
  // Names of the passes that will run, in submission order. Throws std::logic_error if a read
  // resource is produced by no pass earlier in the list or two passes share a name (wiring
  // mistakes, not user input). The renderer calls it on every frame in debug builds and tests.
  std::vector<std::string> compile() const;
  // Runs the culled list; `wrapper` wraps each pass (timing, debug groups). Transient textures
  // come from `allocator` (required when the graph declares any that a live pass uses).
  void execute(const std::function<void(const Pass&, const std::function<void()>&)>& wrapper,
               TransientAllocator* allocator = nullptr) const;
  // The transient textures live passes use, with the live pass indices of their first and last use.
  struct Lifetime {
    std::string resource;
    TextureDesc desc;
    size_t first = 0, last = 0;
  };
  std::vector<Lifetime> transientLifetimes() const;
  void clear();
  const std::vector<Pass>& passes() const { return passes_; }

 private:
  std::vector<bool> liveMask() const;
  void checkTransients() const;
  std::vector<Pass> passes_;
  std::vector<std::string> sinks_;
  std::vector<std::string> imports_;
  std::vector<std::pair<std::string, TextureDesc>> transients_;
  mutable std::map<std::string, void*> lent_;  // during execute
};

}  // namespace sl
