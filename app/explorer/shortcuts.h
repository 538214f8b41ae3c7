// Keyboard shortcuts of the explorer: one table that both the key handling and the help window
// (F1 or ?) read, so the help always lists exactly what the keys do.
#pragma once

#include "explorer/explorer_state.h"

#include <string>
#include <vector>

struct GLFWwindow;

namespace sl {

struct Shortcut {
  std::string keys;    // as shown: "Ctrl + =", "hold M"
  std::string action;  // what it does
  std::string group;   // heading in the help window
};

// Every shortcut and mouse control, in the help window's order.
const std::vector<Shortcut>& explorerShortcuts();

constexpr float kMinUiScale = 0.75f, kMaxUiScale = 2.5f, kUiScaleStep = 0.125f;
float steppedUiScale(float scale, int steps);  // clamped to [kMinUiScale, kMaxUiScale]

// Key presses are recorded from GLFW's key callback, not read from ImGui 1.86's io.KeysDown: a
// tap shorter than a frame (common at llvmpipe's frame rates, and what xdotool sends) sets and
// clears KeysDown within one poll, so ImGui never sees it. Install before the ImGui backend,
// which chains to the callback it finds; clear before each poll.
void installKeyPressRecorder(GLFWwindow* window);
void clearKeyPresses();
// After ImGui::NewFrame: hands ImGui the releases of keys pressed and released since the frame
// before (it has now seen them down once; see recordKey in shortcuts.cpp).
void releaseKeysSeenDown();
void recordKeyPress(int key, int mods);  // what the callback does for a press (tests call it too)
// The GLFW modifier bits held when `key` (a GLFW key code) was pressed since the last clear, or
// -1 when it was not pressed (key repeats do not count).
int keyPressMods(int key);
// Pressed since the last clear with Ctrl held (ctrl) or without Ctrl (!ctrl).
bool keyPressed(int key, bool ctrl = false);

// Reads this frame's key presses (ImGui's view of GLFW keys; nothing while a text field has the
// keyboard) and applies them to the state. Call between ImGui::NewFrame and drawing the panels.
void handleShortcuts(ExplorerState& state);
// The help window, when state.showHelp.
void drawHelpWindow(ExplorerState& state);

}  // namespace sl
