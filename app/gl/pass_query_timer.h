// GL timestamp queries around named passes, read back either at once (the frame's own times: the
// bench and the command line, which wait for the frame anyway) or later, when they are
// available: the explorer then shows the newest frame whose times have arrived, a frame or two
// old, and the CPU never waits for the GPU to finish the frame it just queued (reading every
// query at once did: a stall of each frame on a GPU). Queries are reused between frames.
#pragma once

#include <epoxy/gl.h>

#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace sl {

class PassQueryTimer {
 public:
  using Times = std::vector<std::pair<std::string, double>>;  // pass name, milliseconds
  PassQueryTimer() = default;
  ~PassQueryTimer();
  PassQueryTimer(const PassQueryTimer&) = delete;
  PassQueryTimer& operator=(const PassQueryTimer&) = delete;

  void beginPass();                       // a timestamp before the pass's commands
  void endPass(const std::string& name);  // and after them
  // Closes the frame. With `wait` its own times go to `out` (waiting for them); otherwise the
  // newest earlier or current frame whose times have all arrived does, without waiting. False
  // when no frame's times are ready (`out` untouched).
  bool endFrame(bool wait, Times& out);
  int pendingFrames() const { return static_cast<int>(pending_.size()); }

 private:
  struct Frame {
    std::vector<std::string> names;
    std::vector<std::pair<GLuint, GLuint>> queries;
  };
  GLuint acquire();
  bool available(const Frame& f) const;
  void read(Frame& f, Times& out);  // the results, and the queries back to the pool
  void release(Frame& f);
  Frame current_;
  GLuint open_ = 0;  // the begin query of the pass being timed
  std::deque<Frame> pending_;
  std::vector<GLuint> pool_;
};

}  // namespace sl
