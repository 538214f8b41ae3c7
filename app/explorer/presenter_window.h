// Presenter mode fills the display the window is on (#23): the window becomes borderless over
// that monitor's work area while the tour is in presenter mode (--presenter or F5), and gets its
// size, position and frame back when it leaves. --monitor N chooses the display instead.
#pragma once

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <string>

namespace sl {

// The monitor the window overlaps most, or monitor `index` (1-based) when index > 0; null when
// the display has none (or not that many).
GLFWmonitor* presenterMonitor(GLFWwindow* window, int index);
// "" when `index` (0 = the window's own) names a monitor of this display, else the message for
// --monitor.
std::string checkMonitorIndex(int index);

class PresenterWindow {
 public:
  // Called once per frame with the tour's presenter flag: fills or restores on a change.
  void follow(GLFWwindow* window, bool presenter, int monitorIndex);

 private:
  bool filled_ = false;
  int x_ = 0, y_ = 0, width_ = 0, height_ = 0;  // the window before it filled the monitor
};

}  // namespace sl
