#include "explorer/settings.h"

#include "explorer/explorer_state.h"
#include "technique.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace sl {

namespace fs = std::filesystem;
using nlohmann::json;

std::string defaultSettingsPath() {
  if (const char* explicitPath = std::getenv("SHADOWLAB_SETTINGS"); explicitPath && *explicitPath) return explicitPath;
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config)
    return (fs::path(config) / "shadowlab" / "settings.json").string();
  if (const char* home = std::getenv("HOME"); home && *home)
    return (fs::path(home) / ".config" / "shadowlab" / "settings.json").string();
  return "";
}

std::string settingsToJson(const ExplorerSettings& s) {
  json j;
  j["version"] = 1;
  j["scene"] = s.scene;
  j["viewports"] = json::array();
  for (const ViewportSettings& v : s.viewports)
    j["viewports"].push_back(
        {{"preset", v.preset}, {"params", v.params}, {"enlarged_view", v.enlargedView}, {"layout", v.layout}});
  j["views"] = s.views;
  j["ui_scale"] = s.uiScale;
  j["camera_speed"] = s.cameraSpeed;
  j["screenshot_dir"] = s.screenshotDir;
  j["link_all"] = s.linkAll;
  j["colour_keys"] = s.colourKeys;
  j["linked"] = s.linked;
  return j.dump(2) + "\n";
}

namespace {

// Optional field of a given JSON type; a present field of another type is an error.
template <typename T>
void readField(const json& j, const char* key, T& out) {
  if (!j.contains(key)) return;
  try {
    out = j.at(key).get<T>();
  } catch (const json::exception&) {
    throw std::runtime_error(std::string("field '") + key + "' has the wrong type (" + j.at(key).type_name() + ")");
  }
}

ViewportSettings viewportFromJson(const json& v) {
  if (!v.is_object()) throw std::runtime_error("a 'viewports' entry is not an object");
  ViewportSettings vs;
  readField(v, "preset", vs.preset);
  readField(v, "params", vs.params);
  readField(v, "enlarged_view", vs.enlargedView);
  readField(v, "layout", vs.layout);
  if (vs.preset.empty()) throw std::runtime_error("a 'viewports' entry has no 'preset'");
  for (const auto& [key, value] : vs.params)
    if (!std::isfinite(value)) throw std::runtime_error("parameter '" + key + "' is not a finite number");
  return vs;
}

std::string timeStamp() {
  std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y%m%d-%H%M%S", &local);
  return buffer;
}

}  // namespace

ExplorerSettings settingsFromJson(const std::string& text) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {  // a parse error, or a number out of range (1e999)
    throw std::runtime_error(std::string("not JSON: ") + e.what());
  }
  if (!j.is_object()) throw std::runtime_error("not a JSON object");
  ExplorerSettings s;
  readField(j, "scene", s.scene);
  if (j.contains("viewports")) {
    if (!j["viewports"].is_array()) throw std::runtime_error("field 'viewports' is not an array");
    for (const json& v : j["viewports"]) s.viewports.push_back(viewportFromJson(v));
  }
  if (s.viewports.size() > size_t(kMaxViewports)) throw std::runtime_error("more than 4 viewports");
  readField(j, "views", s.views);
  readField(j, "ui_scale", s.uiScale);
  readField(j, "camera_speed", s.cameraSpeed);
  readField(j, "screenshot_dir", s.screenshotDir);
  readField(j, "link_all", s.linkAll);
  readField(j, "colour_keys", s.colourKeys);
  readField(j, "linked", s.linked);
  if (!std::isfinite(s.uiScale) || !std::isfinite(s.cameraSpeed))
    throw std::runtime_error("ui_scale or camera_speed is not a finite number");
  // Out-of-range numbers are a stale preference, not a corrupt file: clamp them.
  s.uiScale = std::clamp(s.uiScale, 0.5f, 3.0f);
  s.cameraSpeed = s.cameraSpeed <= 0.0f ? 0.0f : std::clamp(s.cameraSpeed, 1e-4f, 10.0f);
  return s;
}

SettingsLoad loadSettings(const std::string& path) {
  SettingsLoad result;
  std::error_code ec;
  if (path.empty() || !fs::exists(path, ec)) return result;
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  try {
    if (!in) throw std::runtime_error("cannot be read");
    result.settings = settingsFromJson(text.str());
  } catch (const std::exception& e) {
    const std::string aside = path + ".bad-" + timeStamp();
    fs::rename(path, aside, ec);
    result.problem = "settings file " + path + " is corrupt (" + e.what() + "); " +
                     (ec ? "could not set it aside (" + ec.message() + ")" : "set aside as " + aside) +
                     "; starting with the defaults";
  }
  return result;
}

void saveSettings(const std::string& path, const ExplorerSettings& settings) {
  if (path.empty()) throw std::runtime_error("no settings path");
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << settingsToJson(settings);
    out.flush();
    if (!out) throw std::runtime_error("could not write settings file " + temporary);
  }
  fs::rename(temporary, target, ec);
  if (ec) throw std::runtime_error("could not replace settings file " + path + ": " + ec.message());
}

ExplorerSettings captureSettings(const ExplorerState& state) {
  ExplorerSettings s;
  s.scene = state.sceneLabel;
  for (int i = 0; i < state.viewportCount && i < int(state.slots.size()); ++i) {
    const ViewportSlot& slot = state.slots[size_t(i)];
    if (!slot.viewport) continue;
    const Technique& t = slot.viewport->technique;
    ViewportSettings v{t.presetId, {}, slot.enlargedView, ""};
    try {
      const Technique preset = makeTechnique(t.presetId);
      if (t.layout != preset.layout) v.layout = t.layout->id();
      for (const ParamDecl& d : t.params.decls())
        if (d.key != kLayoutParam && (!preset.params.has(d.key) || preset.params.get(d.key) != t.params.get(d.key)))
          v.params[d.key] = t.params.get(d.key);
    } catch (const std::exception&) {
    }
    s.viewports.push_back(std::move(v));
  }
  s.views.assign(state.selectedViews.begin(), state.selectedViews.end());
  s.uiScale = state.uiScale;
  s.cameraSpeed = state.camera.speedFactor();
  s.screenshotDir = state.screenshotDir;
  s.linkAll = state.linkAllParams;
  s.colourKeys = state.showColourKeys;
  s.linked.assign(state.linkedParams.begin(), state.linkedParams.end());
  return s;
}

}  // namespace sl
