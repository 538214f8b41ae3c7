#include "explorer/explorer_window.h"

#include "explorer/shortcuts.h"
#include "explorer/ui_scale.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdlib>

namespace sl {

namespace {
std::string g_lastGlfwError;
void rememberGlfwError(int code, const char* description) {
  g_lastGlfwError = description ? description : ("GLFW error " + std::to_string(code));
}
}  // namespace

void installGlfwErrorRecorder() { glfwSetErrorCallback(rememberGlfwError); }

const std::string& lastGlfwError() { return g_lastGlfwError; }

bool displayConfigured() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 && *x11) || (wayland && *wayland);
}

GLFWwindow* createExplorerWindow(const ExplorerOptions& options) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
  glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);  // the renderer writes display-ready colours
  return glfwCreateWindow(std::max(320, options.width), std::max(240, options.height), "shadowlab explorer", nullptr,
                          nullptr);
}

void setUpExplorerImGui(GLFWwindow* window, float uiScale) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is fixed; do not litter the working directory
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 0.0f;
  style.FrameRounding = 3.0f;
  style.GrabRounding = 3.0f;
  style.ItemSpacing = ImVec2(8, 5);
  style.Colors[ImGuiCol_PlotHistogram] = ImVec4(0.30f, 0.62f, 0.95f, 1.0f);  // timing bars

  ImGui_ImplGlfw_InitForOpenGL(window, true);
  // After the backend: the recorder sees each key first and hands it on to the backend's
  // callback, holding back a release ImGui has not yet seen pressed (shortcuts.cpp).
  installKeyPressRecorder(window);
  ImGui_ImplOpenGL3_Init("#version 450");
  applyUiScale(uiScale);  // loads the font (16 px x scale)
}

void shutDownExplorerImGui() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

}  // namespace sl
