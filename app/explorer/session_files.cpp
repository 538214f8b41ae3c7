#include "explorer/session_files.h"

#include "explorer/error_panel.h"
#include "explorer/screenshot.h"
#include "technique.h"

#include <GLFW/glfw3.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace sl {

namespace {

constexpr double kSettingsCheckSeconds = 2.0;  // a crash loses at most this much

std::string lastSavedSettings;  // JSON last written (or read), to skip unchanged saves
double lastSettingsCheck = -1e9;

// "key=value" for makeTechnique: enums and bools by name (as --set takes them), numbers exactly
// (%.17g: std::to_string would round a 1e-5 bias away). Throws ParamError for an unknown key.
std::vector<std::string> settingsOverrides(const ViewportSettings& v) {
  std::vector<std::string> overrides;  // the layout first: the values may belong to it
  if (!v.layout.empty()) overrides.push_back(std::string(kLayoutParam) + "=" + v.layout);
  const Technique probe = makeTechnique(v.preset, overrides);
  for (const auto& [key, value] : v.params) {
    const ParamDecl* decl = probe.params.find(key);
    if (!decl) throw ParamError("preset '" + v.preset + "' has no parameter '" + key + "'");
    if (decl->type == ParamType::Enum || decl->type == ParamType::Bool) {
      const long index = std::lround(value);
      if (decl->type == ParamType::Enum && (index < 0 || index >= long(decl->choices.size())))
        throw ParamError(key + ": saved choice " + std::to_string(index) + " is not one of " + describeRange(*decl));
      overrides.push_back(key + "=" + formatValue(*decl, double(index)));
      continue;
    }
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    overrides.push_back(key + "=" + buffer);
  }
  return overrides;
}

}  // namespace

void reportStatus(ExplorerState& state, const std::string& text, bool problem) {
  state.statusLine = text;
  state.statusLineTime = glfwGetTime();
  (problem ? std::cerr : std::cout) << "shadowlab: " << text << std::endl;
}

std::string exportDir(const ExplorerState& state) {
  return state.screenshotDir.empty() ? defaultScreenshotDir() : state.screenshotDir;
}

void saveRequestedScreenshots(ExplorerState& state, int framebufferWidth, int framebufferHeight) {
  if (!state.screenshotRequested && !state.viewportShotsRequested) return;
  const std::string dir = exportDir(state);
  if (std::string problem = ensureFolder(dir); !problem.empty()) {
    state.screenshotRequested = state.viewportShotsRequested = false;
    reportStatus(state, problem, true);
    return;
  }
  const std::filesystem::path folder(dir);
  std::string written, failed;
  if (state.screenshotRequested) {
    const std::string path = (folder / timestampedScreenshotName()).string();
    const std::string error = writeWindowPng(framebufferWidth, framebufferHeight, path);
    (error.empty() ? written : failed) += error.empty() ? std::filesystem::path(path).filename().string() : error;
  }
  if (state.viewportShotsRequested) {
    for (int i = 0; i < state.viewportCount && i < int(state.slots.size()); ++i) {
      const ViewportSlot& slot = state.slots[size_t(i)];
      if (!slot.viewport) continue;
      const Viewport& vp = *slot.viewport;
      const Texture2D* image = vp.colorTexture();
      std::string suffix = "-" + std::to_string(i + 1) + "-" + vp.technique.presetId;
      if (!slot.enlargedView.empty()) {
        image = slot.enlargedView == ErrorPanel::kViewName && state.errorPanel ? state.errorPanel->errorTexture(i)
                                                                               : vp.viewTexture(slot.enlargedView);
        suffix += "-" + slot.enlargedView;
      }
      const std::string path = (folder / timestampedName(suffix + ".png")).string();
      const std::string error =
          image ? writeTexturePng(*image, path) : "viewport " + std::to_string(i + 1) + " has no image";
      if (error.empty())
        written += (written.empty() ? "" : ", ") + std::filesystem::path(path).filename().string();
      else
        failed += (failed.empty() ? "" : "; ") + error;
    }
  }
  state.screenshotRequested = state.viewportShotsRequested = false;
  if (!failed.empty())
    reportStatus(state, "screenshot failed: " + failed, true);
  else
    reportStatus(state, "saved " + written + " in " + dir);
}

void exportAccuracy(ExplorerState& state) {
  if (!state.errorPanel) return;
  try {
    const std::string dir = exportDir(state);
    const std::string csv = writeTextFile(dir, timestampedName("-accuracy.csv"), state.errorPanel->accuracyCsv(state));
    const std::string svg = writeTextFile(dir, timestampedName("-error-vs-time.svg"), state.errorPanel->chartSvg());
    reportStatus(state, "saved " + csv + " and " + svg);
  } catch (const std::exception& e) {
    reportStatus(state, std::string("export failed: ") + e.what(), true);
  }
}

void startLayout(ExplorerOptions& options, const ExplorerSettings* saved, std::string& problems) {
  if (saved && !options.sceneGiven && !saved->scene.empty()) {
    options.scene = saved->scene;
    options.fromSettings = true;
  }
  std::vector<ViewportSettings> usable;
  if (saved && !options.layoutGiven) {
    for (const ViewportSettings& v : saved->viewports) {
      try {
        makeTechnique(v.preset, settingsOverrides(v));
        usable.push_back(v);
      } catch (const std::exception& e) {
        problems += std::string(problems.empty() ? "" : "; ") + "saved viewport dropped: " + e.what();
      }
    }
  }
  if (usable.empty()) {
    if (!options.layoutGiven) {
      options.firstStartDefaults = true;
      options.compareTechniques = {"pcf"};
      options.debugViews = {"aliasing", "shadowmap", "texels"};
    }
    return;
  }
  options.fromSettings = true;
  options.compareTechniques.clear();
  options.compareOverrides.clear();
  options.enlargedViews.clear();
  for (size_t i = 0; i < usable.size(); ++i) {
    const std::vector<std::string> overrides = settingsOverrides(usable[i]);
    if (i == 0) {
      options.technique = usable[i].preset;
      options.overrides = overrides;
    } else {
      options.compareTechniques.push_back(usable[i].preset);
      options.compareOverrides.push_back(overrides);
    }
    options.enlargedViews.push_back(usable[i].enlargedView);
  }
  options.debugViews = saved->views;
}

void applyStateSettings(ExplorerState& state, const ExplorerSettings& settings) {
  state.uiScale = settings.uiScale;
  if (settings.cameraSpeed > 0.0f) state.camera.setSpeedFactor(settings.cameraSpeed);
  state.screenshotDir = settings.screenshotDir;
  state.linkAllParams = settings.linkAll;
  state.showColourKeys = settings.colourKeys;
  state.linkedParams.insert(settings.linked.begin(), settings.linked.end());
}

void saveSettingsIfChanged(ExplorerState& state, double now, bool force) {
  if (state.settingsPath.empty()) return;
  if (!force && now - lastSettingsCheck < kSettingsCheckSeconds) return;
  lastSettingsCheck = now;
  const ExplorerSettings current = captureSettings(state);
  const std::string json = settingsToJson(current);
  if (json == lastSavedSettings) return;
  try {
    saveSettings(state.settingsPath, current);
    lastSavedSettings = json;
  } catch (const std::exception& e) {
    const std::string message = std::string("settings not saved: ") + e.what();
    if (state.settingsMessage != message) std::cerr << "shadowlab: " << message << "\n";
    state.settingsMessage = message;
  }
}

}  // namespace sl
