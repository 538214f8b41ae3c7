// The explorer's settings between runs: last scene, viewports (presets, changed parameters,
// enlarged views), debug views, UI scale, camera speed, screenshot folder, linked parameters.
// One JSON file, written atomically (temporary file + rename); a corrupt one is set aside as
// settings.json.bad-<time> and reported, never silently lost and never fatal.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace sl {

struct ExplorerState;

struct ViewportSettings {
  std::string preset;
  std::map<std::string, double> params;  // only those that differ from the preset
  std::string enlargedView;              // "" = colour
  std::string layout;                    // technique.layout by name ("" = the preset's): layouts are
                                         // added over time, so an index would change meaning
};

struct ExplorerSettings {
  std::string scene;
  std::vector<ViewportSettings> viewports;  // the shown ones, 1 to 4
  std::vector<std::string> views;           // debug views selected as thumbnails
  float uiScale = 1.0f;
  float cameraSpeed = 0.0f;  // scene diagonals per second; 0 = the default
  std::string screenshotDir;
  bool linkAll = false;
  bool colourKeys = true;
  std::vector<std::string> linked;
};

// $SHADOWLAB_SETTINGS if set (a file path), else $XDG_CONFIG_HOME/shadowlab/settings.json,
// else ~/.config/shadowlab/settings.json; "" when none of these is known.
std::string defaultSettingsPath();

struct SettingsLoad {
  std::optional<ExplorerSettings> settings;  // empty: no file, or it was set aside
  std::string problem;                       // "" or what was wrong and where the file went
};
// Reads `path`. A missing file is no problem; one that cannot be parsed or has fields of the
// wrong type is renamed to <path>.bad-<YYYYmmdd-HHMMSS> and `problem` says so (naming both).
SettingsLoad loadSettings(const std::string& path);
// Writes `path` (creating its folder) via <path>.tmp and rename, so a crash mid-write leaves the
// old file. Throws std::runtime_error naming the file.
void saveSettings(const std::string& path, const ExplorerSettings& settings);

std::string settingsToJson(const ExplorerSettings& settings);
// Throws std::runtime_error saying what is wrong (for loadSettings and tests).
ExplorerSettings settingsFromJson(const std::string& text);

// What the window shows now, as settings (parameters relative to each viewport's preset).
ExplorerSettings captureSettings(const ExplorerState& state);

}  // namespace sl
