// The interactive window: one or more viewports comparing shadow techniques on the same scene
// and camera, with a parameter panel generated from each technique's declarations.
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace sl {

struct ExplorerOptions {
  std::string scene = "basic";         // builtin id or path to a .json/.gltf/.glb
  std::string technique = "standard";  // preset id for the first viewport
  std::vector<std::string> overrides;  // "key=value" applied to the first viewport's technique
  std::string camera;                  // named scene camera to start from ("" = the first one)
  int width = 1280, height = 720;      // window size in screen coordinates
  int maxFrames = 0;                   // 0 = until the window is closed
  std::string screenshotOnExit;        // PNG of the whole window written before exiting, or ""
  std::string shaderDir, assetsDir;    // "" = defaultShaderDir() / defaultAssetsDir()
  // Start-up state of the window, so a comparison can be scripted (slides, smoke tests).
  std::vector<std::string> compareTechniques;              // presets for viewports 2..4 (1 -> 2 viewports, 2-3 -> 4)
  std::vector<std::string> debugViews;                     // debug views shown as thumbnails from the start
  bool magnifier = false;                                  // lens on without holding M
  bool visibilityPlot = false;                             // visibility-vs-depth plot on without holding V
  bool dpdsPlot = false;                                   // the live dp/ds window open at start
  std::vector<std::string> enlargedViews;                  // per viewport: debug view in the big image ("" = colour)
  std::vector<std::vector<std::string>> compareOverrides;  // "key=value" per compared viewport
  bool setLight = false;                                   // replace the scene's light direction by lightAngles
  glm::vec2 lightAngles{0.0f};                             // degrees: azimuth about +y from +z, elevation
  // Settings between runs (app/explorer/settings.h): "" = none read or written. When the command
  // line names a scene, technique, comparison or view (`layoutGiven`), that wins over the saved
  // scene and viewports; UI scale, camera speed and folders still come from the file.
  std::string settingsPath;
  bool sceneGiven = false, layoutGiven = false;
  // Neither the command line nor settings chose the viewports: start as the README shows, two
  // techniques side by side with debug views (a lecture's first slide, not one bare image).
  bool firstStartDefaults = false;
  bool fromSettings = false;  // scene/viewports came from the settings file: be lenient with them
  float uiScale = 0.0f;       // UI size (1 = 16 px font); 0 = from the settings file, else 1
  bool showHelp = false;      // open the keys window at start (scripted screenshots of it)
  bool saveOnExit = false;    // last frame: window + viewport images + table/chart into the screenshot folder
  std::string screenshotDir;  // "" = from the settings file, else defaultScreenshotDir()
  double soakSeconds = 0;     // > 0: unattended reliability run (app/explorer/soak.h), then exit
  std::string tour;           // lecture tour to play (explorer/tour_player.h), or ""
  int tourStep = 1;           // its first step shown (1-based)
  bool presenter = false;     // start the tour in presenter mode
  int monitor = 0;            // the display presenter mode fills (1-based; 0 = the window's)
};

// Opens the window and runs until it is closed (or maxFrames have been drawn). Returns the
// process exit code: 0 after a clean exit, 1 for bad options (unknown scene, preset, camera or
// override) or a failed last frame in --frames mode, 2 when there is no display to open a
// window on (the message then says how to render headless instead).
int runExplorer(const ExplorerOptions& options);

}  // namespace sl
