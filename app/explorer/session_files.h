// What the explorer writes while it runs: requested screenshots and exports (into the chosen
// folder, full path reported on screen) and the settings file (saved when it changed).
#pragma once

#include "explorer/explorer_state.h"
#include "explorer/settings.h"

#include <string>

namespace sl {

// Sets the status line (shown near the top of the side panel and as a banner for a while) and
// prints it to stdout, so a capture's path is never below the fold.
void reportStatus(ExplorerState& state, const std::string& text, bool problem = false);
// The folder captures go to: state.screenshotDir, or defaultScreenshotDir() when empty.
std::string exportDir(const ExplorerState& state);
// Window capture and/or per-viewport images requested this frame (call after ImGui rendered,
// before swapping). Clears the requests.
void saveRequestedScreenshots(ExplorerState& state, int framebufferWidth, int framebufferHeight);
// The accuracy table as CSV and the error-vs-time chart as SVG, into exportDir.
void exportAccuracy(ExplorerState& state);

// The scene and viewports of saved settings into the start options (unless the command line
// chose them); presets or parameters that no longer exist are dropped, named in `problems`.
// Without saved viewports and without a command-line choice, the first-start layout: two
// techniques side by side with the aliasing and shadow-map views.
void startLayout(ExplorerOptions& options, const ExplorerSettings* saved, std::string& problems);
// Applies loaded settings to a state that prepareState set up (after the command line: the
// caller decides which parts the command line overrides). Unknown presets, parameters or views
// are skipped with a message in state.settingsMessage; nothing throws.
void applyStateSettings(ExplorerState& state, const ExplorerSettings& settings);
// Saves the settings when they differ from what was last written (checked at most every
// `intervalSeconds`; force = at exit). Problems go to state.settingsMessage and stderr.
void saveSettingsIfChanged(ExplorerState& state, double now, bool force);

}  // namespace sl
