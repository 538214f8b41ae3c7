// The GL side of the frame graph's transient textures: a pool that lends textures by their
// TextureDesc, takes them back after their last pass, and keeps them for later frames (and for
// later passes of the same frame whose lifetimes do not overlap: two viewports' blur scratch
// targets of one size are one texture). Textures unused for a while are freed, so switching
// technique does not keep the old one's targets.
#pragma once

#include "gl/gl_util.h"
#include "part/frame_graph.h"

#include <memory>
#include <string>
#include <vector>

namespace sl {

class TransientTextures : public TransientAllocator {
 public:
  void* acquire(const TextureDesc& desc, const std::string& name) override;
  void release(void* texture) override;
  // Before a frame's execute: everything is free again (also after a pass threw), and textures
  // no frame has used for `kKeepFrames` frames are deleted.
  void beginFrame();
  int textures() const { return static_cast<int>(entries_.size()); }
  long long texels() const;  // what the pool holds, for the memory side of a frame's cost
  // A frame here is one Renderer::render call. `shadowlab bench` renders its entries in turn, one
  // call each (43 presets in the every-preset table): with 8, a texture one entry needs was gone
  // again by its next frame, and the entry paid a 2048² allocation each frame (vsm's frame
  // measured 194 ms of which its passes took 88). Idle textures cost memory only.
  static constexpr int kKeepFrames = 64;

 private:
  struct Entry {
    TextureDesc desc;
    std::unique_ptr<Texture2D> texture;
    bool inUse = false;
    int idleFrames = 0;
  };
  std::vector<Entry> entries_;
};

// The texture the frame graph lent to `resource` for the pass that is running (a transient the
// pass declared; part/frame_graph.h). Throws std::logic_error when there is none.
Texture2D& transientTexture(const FrameGraph& graph, const std::string& resource);

}  // namespace sl
