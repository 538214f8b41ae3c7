// The timer queries around passes: waited for, a frame's own passes in order; not waited for,
// the newest frame whose times have arrived, with its own names, and no query left behind.
// (llvmpipe's timestamps do not measure the work, so only names, order and sanity are checked.)
#include "gl/headless_context.h"
#include "gl/pass_query_timer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sl {
namespace {

// A command to time (a surfaceless context has no default framebuffer to clear).
void someWork() {
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, 1 << 16, nullptr, 0);
  const uint32_t value = 7;
  glClearNamedBufferData(buffer, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
  glDeleteBuffers(1, &buffer);
}

std::vector<std::string> names(const PassQueryTimer::Times& t) {
  std::vector<std::string> n;
  for (const auto& [name, ms] : t) {
    n.push_back(name);
    EXPECT_TRUE(std::isfinite(ms) && ms >= 0.0) << name << ": " << ms;
  }
  return n;
}

TEST(PassQueryTimer, WaitingGivesTheFramesOwnPassesInOrder) {
  HeadlessContext context;
  PassQueryTimer timer;
  for (int frame = 0; frame < 3; ++frame) {
    for (const char* pass : {"gbuffer", "shadowmap[0]", "shade[0]"}) {
      timer.beginPass();
      someWork();
      timer.endPass(pass);
    }
    PassQueryTimer::Times t;
    ASSERT_TRUE(timer.endFrame(true, t));
    EXPECT_EQ(names(t), (std::vector<std::string>{"gbuffer", "shadowmap[0]", "shade[0]"}));
    EXPECT_EQ(timer.pendingFrames(), 0);
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(PassQueryTimer, NotWaitingGivesTheNewestArrivedFrameAndKeepsFewPending) {
  HeadlessContext context;
  PassQueryTimer timer;
  PassQueryTimer::Times t;
  // Frames queued one after another: whatever arrives is one whole frame, named as it was.
  for (int frame = 0; frame < 10; ++frame) {
    timer.beginPass();
    someWork();
    timer.endPass("frame " + std::to_string(frame));
    if (timer.endFrame(false, t)) {
      ASSERT_EQ(t.size(), 1u);
      EXPECT_LE(std::stoi(t[0].first.substr(6)), frame);
    }
    EXPECT_LE(timer.pendingFrames(), 5) << "frames whose times never arrive are dropped";
  }
  // Once the GPU has finished, the next frame's close gives the newest of those frames' times
  // (or its own) and nothing older.
  glFinish();
  timer.beginPass();
  someWork();
  timer.endPass("last");
  ASSERT_TRUE(timer.endFrame(false, t));
  ASSERT_EQ(t.size(), 1u);
  EXPECT_TRUE(t[0].first == "last" || t[0].first == "frame 9") << t[0].first;
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace sl
