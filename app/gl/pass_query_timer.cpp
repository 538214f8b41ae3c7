#include "gl/pass_query_timer.h"

namespace sl {

namespace {

// Frames whose times have not arrived that are kept; an older one is dropped unread (a GPU this
// far behind is bounded by the driver's own queue well before).
constexpr size_t kMaxPending = 4;

}  // namespace

PassQueryTimer::~PassQueryTimer() {
  release(current_);
  for (Frame& f : pending_) release(f);
  if (open_) pool_.push_back(open_);
  if (!pool_.empty()) glDeleteQueries(static_cast<GLsizei>(pool_.size()), pool_.data());
}

GLuint PassQueryTimer::acquire() {
  if (pool_.empty()) {
    GLuint q = 0;
    glGenQueries(1, &q);
    return q;
  }
  const GLuint q = pool_.back();
  pool_.pop_back();
  return q;
}

void PassQueryTimer::beginPass() {
  if (!open_) open_ = acquire();
  glQueryCounter(open_, GL_TIMESTAMP);
}

void PassQueryTimer::endPass(const std::string& name) {
  if (!open_) return;  // no beginPass
  const GLuint end = acquire();
  glQueryCounter(end, GL_TIMESTAMP);
  current_.names.push_back(name);
  current_.queries.emplace_back(open_, end);
  open_ = 0;
}

// Timestamps complete in order: the frame's last one available means all are.
bool PassQueryTimer::available(const Frame& f) const {
  if (f.queries.empty()) return true;
  GLuint done = 0;
  glGetQueryObjectuiv(f.queries.back().second, GL_QUERY_RESULT_AVAILABLE, &done);
  return done != 0;
}

void PassQueryTimer::read(Frame& f, Times& out) {
  out.clear();
  for (size_t k = 0; k < f.queries.size(); ++k) {
    GLuint64 a = 0, b = 0;
    glGetQueryObjectui64v(f.queries[k].first, GL_QUERY_RESULT, &a);
    glGetQueryObjectui64v(f.queries[k].second, GL_QUERY_RESULT, &b);
    out.emplace_back(f.names[k], b >= a ? static_cast<double>(b - a) * 1e-6 : 0.0);
  }
  release(f);
}

void PassQueryTimer::release(Frame& f) {
  for (const auto& [a, b] : f.queries) {
    pool_.push_back(a);
    pool_.push_back(b);
  }
  f.queries.clear();
  f.names.clear();
}

bool PassQueryTimer::endFrame(bool wait, Times& out) {
  Frame frame = std::move(current_);
  current_ = Frame{};
  if (wait) {
    read(frame, out);
    return true;
  }
  pending_.push_back(std::move(frame));
  // The newest frame whose times have arrived; the older ones are superseded.
  int newest = -1;
  for (size_t i = 0; i < pending_.size(); ++i)
    if (available(pending_[i])) newest = static_cast<int>(i);
  if (newest < 0) {
    while (pending_.size() > kMaxPending) {
      release(pending_.front());
      pending_.pop_front();
    }
    return false;
  }
  for (int i = 0; i < newest; ++i) {
    release(pending_.front());
    pending_.pop_front();
  }
  read(pending_.front(), out);
  pending_.pop_front();
  return true;
}

}  // namespace sl
