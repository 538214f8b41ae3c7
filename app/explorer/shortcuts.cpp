#include "explorer/shortcuts.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace sl {

const std::vector<Shortcut>& explorerShortcuts() {
  static const std::vector<Shortcut> table = {
      {"F1  or  ?", "show / hide this help", "Window"},
      {"Ctrl + =  /  Ctrl + -", "larger / smaller UI (for a projector)", "Window"},
      {"Ctrl + 0", "UI back to 100 %", "Window"},
      {"1  2  3  4", "one to four viewports (three in a row)", "Window"},
      {"Tab  /  Shift + Tab", "cycle the big images: colour, then each debug view", "Window"},
      {"K", "show / hide the colour keys over the debug views", "Window"},
      {"F12  or  Ctrl + S", "screenshot of the whole window", "Window"},
      {"Shift + F12", "clean images of each viewport (no UI)", "Window"},
      {"Ctrl + Q", "quit (settings are saved)", "Window"},
      {"P", "pause / resume scene time (animation)", "Time"},
      {"F", "freeze frames (render nothing new)", "Time"},
      {"N  or  .", "step: render exactly one frame (freezes first)", "Time"},
      {"right-drag", "look around (mouse over a viewport)", "Camera"},
      {"W A S D", "move forward / left / back / right", "Camera"},
      {"Q  /  E", "down / up", "Camera"},
      {"Shift", "move 4x faster", "Camera"},
      {"mouse wheel", "camera speed (x1.25 per notch; also a slider in Camera)", "Camera"},
      {"hold M", "magnifier: 8x, unfiltered pixels", "Tools"},
      {"hold V", "visibility vs receiver depth under the mouse (pre-filtered maps)", "Tools"},
      {"click a thumbnail", "enlarge that debug view; click again for the colour image", "Tools"},
  };
  return table;
}

float steppedUiScale(float scale, int steps) {
  const float stepped = std::round(scale / kUiScaleStep) * kUiScaleStep + float(steps) * kUiScaleStep;
  return std::clamp(stepped, kMinUiScale, kMaxUiScale);
}

namespace {

struct KeyPress {
  int key, mods;
};
std::vector<KeyPress> g_presses;  // since the last clearKeyPresses (one window per process)
GLFWkeyfun g_previousKeyCallback = nullptr;

// Dear ImGui 1.86 reads keys as held-down state at NewFrame: a key pressed and released between
// two frames (a quick tap at 12 fps on llvmpipe, or xdotool) was never seen, so Return did not
// close a Ctrl+click edit box. Its release waits until ImGui has seen it down for one frame.
struct HeldKey {
  GLFWwindow* window;
  int key, scancode, mods;
};
std::vector<int> g_downThisFrame;     // pressed since the last NewFrame
std::vector<HeldKey> g_heldReleases;  // released before ImGui saw them down

void recordKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
  if (action == GLFW_PRESS) {
    recordKeyPress(key, mods);
    g_downThisFrame.push_back(key);
  }
  if (action == GLFW_RELEASE &&
      std::find(g_downThisFrame.begin(), g_downThisFrame.end(), key) != g_downThisFrame.end()) {
    g_heldReleases.push_back({window, key, scancode, mods});
    return;
  }
  if (g_previousKeyCallback) g_previousKeyCallback(window, key, scancode, action, mods);
}

bool pressed(int key) { return keyPressed(key, false); }

}  // namespace

void installKeyPressRecorder(GLFWwindow* window) { g_previousKeyCallback = glfwSetKeyCallback(window, recordKey); }

void clearKeyPresses() { g_presses.clear(); }

void releaseKeysSeenDown() {
  g_downThisFrame.clear();
  const std::vector<HeldKey> held = std::move(g_heldReleases);
  g_heldReleases.clear();
  for (const HeldKey& k : held)
    if (g_previousKeyCallback) g_previousKeyCallback(k.window, k.key, k.scancode, GLFW_RELEASE, k.mods);
}

void recordKeyPress(int key, int mods) { g_presses.push_back({key, mods}); }

int keyPressMods(int key) {
  for (const KeyPress& p : g_presses)
    if (p.key == key) return p.mods;
  return -1;
}

bool keyPressed(int key, bool ctrl) {
  const int mods = keyPressMods(key);
  return mods >= 0 && ((mods & GLFW_MOD_CONTROL) != 0) == ctrl;
}

void handleShortcuts(ExplorerState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  bool question = false;
  for (ImWchar c : io.InputQueueCharacters) question |= c == '?';
  if (keyPressMods(GLFW_KEY_F1) >= 0 || question) state.showHelp = !state.showHelp;
  if (keyPressed(GLFW_KEY_EQUAL, true) || keyPressed(GLFW_KEY_KP_ADD, true))
    state.uiScale = steppedUiScale(state.uiScale, 1);
  if (keyPressed(GLFW_KEY_MINUS, true) || keyPressed(GLFW_KEY_KP_SUBTRACT, true))
    state.uiScale = steppedUiScale(state.uiScale, -1);
  if (keyPressed(GLFW_KEY_0, true)) state.uiScale = 1.0f;
  if (keyPressed(GLFW_KEY_Q, true)) state.quitRequested = true;
  const int shotMods = keyPressMods(GLFW_KEY_F12) >= 0 ? keyPressMods(GLFW_KEY_F12) : keyPressMods(GLFW_KEY_S);
  if (keyPressMods(GLFW_KEY_F12) >= 0 || keyPressed(GLFW_KEY_S, true)) {
    if (shotMods & GLFW_MOD_SHIFT)
      state.viewportShotsRequested = true;
    else
      state.screenshotRequested = true;
  }
  const bool shift = io.KeyShift;
  for (int n = 1; n <= kMaxViewports; ++n)  // GLFW_KEY_1 .. GLFW_KEY_4 are consecutive
    if (pressed(GLFW_KEY_0 + n)) state.viewportCount = n;
  if (pressed(GLFW_KEY_TAB)) cycleEnlargedView(state, (keyPressMods(GLFW_KEY_TAB) & GLFW_MOD_SHIFT) || shift ? -1 : 1);
  if (pressed(GLFW_KEY_P)) state.paused = !state.paused;
  if (pressed(GLFW_KEY_K)) state.showColourKeys = !state.showColourKeys;
  if (pressed(GLFW_KEY_F)) state.frozen = !state.frozen;
  if (pressed(GLFW_KEY_N) || pressed(GLFW_KEY_PERIOD)) {
    state.frozen = true;
    state.stepRequested = true;
  }
}

void drawHelpWindow(ExplorerState& state) {
  if (!state.showHelp) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.94f);
  const ImGuiWindowFlags flags =
      ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse;
  if (!ImGui::Begin("Keys and mouse (F1)", &state.showHelp, flags)) {
    ImGui::End();
    return;
  }
  std::string group;
  if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
    for (const Shortcut& s : explorerShortcuts()) {
      if (s.group != group) {
        group = s.group;
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", group.c_str());
      }
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      ImGui::TextUnformatted(s.keys.c_str());
      ImGui::TableSetColumnIndex(1);
      ImGui::TextUnformatted(s.action.c_str());
    }
    ImGui::EndTable();
  }
  ImGui::TextDisabled("Keys act when no text field is being edited. Camera keys need the mouse over a viewport.");
  ImGui::End();
}

}  // namespace sl
