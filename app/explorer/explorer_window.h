// The explorer's window: GLFW with an OpenGL 4.5 core context, and Dear ImGui on it.
#pragma once

#include "explorer/explorer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <string>

namespace sl {

// DISPLAY or WAYLAND_DISPLAY is set (else the window cannot open: the explorer says how to
// render headless instead).
bool displayConfigured();
// GLFW's errors are kept for the messages of a failed start (lastGlfwError).
void installGlfwErrorRecorder();
const std::string& lastGlfwError();
GLFWwindow* createExplorerWindow(const ExplorerOptions& options);
// The style, the key-press recorder (before the backend, which chains to it), the backends and
// the font at `uiScale`.
void setUpExplorerImGui(GLFWwindow* window, float uiScale);
void shutDownExplorerImGui();

}  // namespace sl
