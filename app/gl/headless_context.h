// An OpenGL 4.5 core context with no window, through EGL: Mesa's surfaceless platform
// (llvmpipe on this machine) or EGL's device platform on a GPU driver without surfaceless.
#pragma once

#include <string>

namespace sl {

class HeadlessContext {
 public:
  // Throws std::runtime_error with what EGL said when no context can be made.
  HeadlessContext();
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;
  const std::string& platform() const { return platform_; }

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string platform_;
};

}  // namespace sl
