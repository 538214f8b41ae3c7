// The ring that lets a status line read GPU counters without waiting for the frame: it returns
// the newest finished copy, never an older one, and never the bytes of a copy not yet made.
#include "gl/headless_context.h"
#include "gl/readback_ring.h"

#include <gtest/gtest.h>

namespace sl {
namespace {

struct Source {
  GLuint buffer = 0;
  Source() {
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, 8, nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  ~Source() { glDeleteBuffers(1, &buffer); }
  void write(uint32_t a, uint32_t b) {
    const uint32_t v[2] = {a, b};
    glNamedBufferSubData(buffer, 0, sizeof v, v);
  }
};

TEST(ReadbackRing, ZerosUntilACopyFinishesThenTheCopiedBytes) {
  HeadlessContext context;
  Source source;
  ReadbackRing ring(8);
  EXPECT_FALSE(ring.ready());
  EXPECT_EQ(ring.value<uint32_t>(1), 0u);
  source.write(7, 11);
  ring.copyFrom(source.buffer);
  source.write(99, 99);  // after the copy was queued: not what it reads
  ring.finish();
  ASSERT_TRUE(ring.ready());
  EXPECT_EQ(ring.value<uint32_t>(0), 7u);
  EXPECT_EQ(ring.value<uint32_t>(1), 11u);
  EXPECT_EQ(ring.pending(), 0);
  EXPECT_EQ(ring.value<uint32_t>(2), 0u) << "past the copied bytes";
}

TEST(ReadbackRing, TheNewestFinishedCopyWinsAndAnOffsetSelectsTheBytes) {
  HeadlessContext context;
  Source source;
  ReadbackRing ring(4, 3);
  for (uint32_t frame = 1; frame <= 5; ++frame) {  // more copies than slots: the oldest are dropped
    source.write(frame, 100 + frame);
    ring.copyFrom(source.buffer, 4);
  }
  glFinish();
  EXPECT_TRUE(ring.poll());
  EXPECT_EQ(ring.value<uint32_t>(0), 105u);
  EXPECT_FALSE(ring.poll()) << "nothing new since";
  // Polled after every frame, it follows the frames one by one.
  for (uint32_t frame = 6; frame <= 8; ++frame) {
    source.write(frame, 100 + frame);
    ring.copyFrom(source.buffer, 4);
    ring.finish();
    EXPECT_EQ(ring.value<uint32_t>(0), 100 + frame);
  }
}

}  // namespace
}  // namespace sl
