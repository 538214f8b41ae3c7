// Keyboard shortcuts of the explorer: one table that both the key handling and the help window
// (F1 or ?) read, so the help always lists exactly what the keys do.
#pragma once

#include "explorer/explorer_state.h"

#include <string>
#include <vector>

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

// Reads this frame's key presses (ImGui's view of GLFW keys; nothing while a text field has the
// keyboard) and applies them to the state. Call between ImGui::NewFrame and drawing the panels.
void handleShortcuts(ExplorerState& state);
// The help window, when state.showHelp.
void drawHelpWindow(ExplorerState& state);

}  // namespace sl
