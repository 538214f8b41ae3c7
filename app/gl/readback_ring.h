// A few bytes of a GPU buffer read back without a stall: each frame copies them on the GPU into
// the next of a ring of staging buffers behind a fence, and the CPU takes the newest copy whose
// fence has passed. A status line then shows numbers a frame or two old instead of making the
// CPU wait for the frame it just queued (on a GPU that wait is the whole frame's work; on
// llvmpipe, which runs the work when it is asked for, it costs nothing either way).
#pragma once

#include <epoxy/gl.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace sl {

class ReadbackRing {
 public:
  explicit ReadbackRing(size_t bytes, int slots = 3);
  ~ReadbackRing();
  ReadbackRing(const ReadbackRing&) = delete;
  ReadbackRing& operator=(const ReadbackRing&) = delete;

  // Queues a copy of `bytes` of `source` from `offset` (after the pass that wrote it and its
  // memory barrier). When every slot still waits for its copy the oldest is dropped rather than
  // waited for, so this never blocks.
  void copyFrom(GLuint source, size_t offset = 0);
  // Takes the newest finished copy, if one finished since the last call; never blocks. True when
  // latest() changed.
  bool poll();
  // Waits for every queued copy (tests, and a command line that reads the last frame's numbers).
  void finish();
  // The newest finished copy (zeros before the first), and how many copies were queued after it.
  const std::vector<uint8_t>& latest() const { return latest_; }
  bool ready() const { return received_ > 0; }
  int pending() const;
  template <class T>
  T value(size_t index) const {
    T v{};
    if ((index + 1) * sizeof(T) <= latest_.size()) std::memcpy(&v, latest_.data() + index * sizeof(T), sizeof(T));
    return v;
  }

 private:
  struct Slot {
    GLuint buffer = 0;
    GLsync fence = nullptr;
    uint64_t serial = 0;  // the order of its copy, so an older copy never replaces a newer one
  };
  void take(Slot& slot);
  // Takes every copy whose fence passes within `timeoutNs` (0: without waiting).
  void collect(GLuint64 timeoutNs);
  std::vector<Slot> slots_;
  std::vector<uint8_t> latest_;
  size_t bytes_;
  int next_ = 0;
  uint64_t queued_ = 0, received_ = 0;
};

}  // namespace sl
