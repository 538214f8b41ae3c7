#include "explorer/presenter_window.h"

#include <algorithm>

namespace sl {

GLFWmonitor* presenterMonitor(GLFWwindow* window, int index) {
  int count = 0;
  GLFWmonitor** monitors = glfwGetMonitors(&count);
  if (count <= 0) return nullptr;
  if (index > 0) return index <= count ? monitors[index - 1] : nullptr;
  int wx = 0, wy = 0, ww = 0, wh = 0;
  glfwGetWindowPos(window, &wx, &wy);
  glfwGetWindowSize(window, &ww, &wh);
  GLFWmonitor* best = glfwGetPrimaryMonitor();
  long bestArea = -1;
  for (int i = 0; i < count; ++i) {
    int mx = 0, my = 0, mw = 0, mh = 0;
    glfwGetMonitorWorkarea(monitors[i], &mx, &my, &mw, &mh);
    const long w = std::max(0, std::min(wx + ww, mx + mw) - std::max(wx, mx));
    const long h = std::max(0, std::min(wy + wh, my + mh) - std::max(wy, my));
    if (w * h > bestArea) bestArea = w * h, best = monitors[i];
  }
  return best;
}

std::string checkMonitorIndex(int index) {
  int count = 0;
  glfwGetMonitors(&count);
  if (index <= 0 || index <= count) return "";
  return "--monitor " + std::to_string(index) + ": this display has " + std::to_string(count) + " monitor" +
         (count == 1 ? "" : "s");
}

void PresenterWindow::follow(GLFWwindow* window, bool presenter, int monitorIndex) {
  if (presenter == filled_) return;
  if (presenter) {
    GLFWmonitor* monitor = presenterMonitor(window, monitorIndex);
    if (!monitor) return;
    glfwGetWindowPos(window, &x_, &y_);
    glfwGetWindowSize(window, &width_, &height_);
    int mx = 0, my = 0, mw = 0, mh = 0;
    glfwGetMonitorWorkarea(monitor, &mx, &my, &mw, &mh);
    glfwSetWindowAttrib(window, GLFW_DECORATED, GLFW_FALSE);
    glfwSetWindowPos(window, mx, my);
    glfwSetWindowSize(window, mw, mh);
  } else {
    glfwSetWindowAttrib(window, GLFW_DECORATED, GLFW_TRUE);
    glfwSetWindowPos(window, x_, y_);
    glfwSetWindowSize(window, width_, height_);
  }
  filled_ = presenter;
}

}  // namespace sl
