#include "gl/readback_ring.h"

#include "gl/gl_util.h"

namespace sl {

ReadbackRing::ReadbackRing(size_t bytes, int slots)
    : slots_(static_cast<size_t>(slots < 1 ? 1 : slots)), latest_(bytes, 0), bytes_(bytes) {
  for (Slot& s : slots_) {
    glCreateBuffers(1, &s.buffer);
    glNamedBufferStorage(s.buffer, static_cast<GLsizeiptr>(bytes), nullptr, 0);
    label(GL_BUFFER, s.buffer, "readback ring slot");
  }
}

ReadbackRing::~ReadbackRing() {
  for (Slot& s : slots_) {
    if (s.fence) glDeleteSync(s.fence);
    glDeleteBuffers(1, &s.buffer);
  }
}

int ReadbackRing::pending() const {
  int n = 0;
  for (const Slot& s : slots_) n += s.fence != nullptr;
  return n;
}

void ReadbackRing::copyFrom(GLuint source, size_t offset) {
  poll();
  Slot& s = slots_[static_cast<size_t>(next_)];
  next_ = (next_ + 1) % static_cast<int>(slots_.size());
  if (s.fence) glDeleteSync(s.fence);  // every slot busy: this slot's older copy is dropped unread
  glCopyNamedBufferSubData(source, s.buffer, static_cast<GLintptr>(offset), 0, static_cast<GLsizeiptr>(bytes_));
  s.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  s.serial = ++queued_;
}

// The copy is complete, so reading the staging buffer does not wait for anything queued after it.
void ReadbackRing::take(Slot& s) {
  glDeleteSync(s.fence);
  s.fence = nullptr;
  if (s.serial <= received_) return;
  glGetNamedBufferSubData(s.buffer, 0, static_cast<GLsizeiptr>(bytes_), latest_.data());
  received_ = s.serial;
}

void ReadbackRing::collect(GLuint64 timeoutNs) {
  for (Slot& s : slots_) {
    if (!s.fence) continue;
    // The flush bit makes sure the fence reaches the GPU, so a later poll sees it pass.
    const GLenum r = glClientWaitSync(s.fence, GL_SYNC_FLUSH_COMMANDS_BIT, timeoutNs);
    if (r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED) take(s);
  }
}

bool ReadbackRing::poll() {
  const uint64_t before = received_;
  collect(0);
  return received_ != before;
}

void ReadbackRing::finish() { collect(10'000'000'000ull); }  // 10 s

}  // namespace sl
