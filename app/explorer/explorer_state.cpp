#include "explorer/explorer_state.h"

#include "explorer/error_panel.h"
#include "technique.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace sl {

float sceneDiagonal(const Scene& scene) {
  Bounds b = scene.boundsAt(0.0);
  return b.empty() ? 10.0f : glm::length(b.extent());
}

void countRenderedFrame(ExplorerState& state, bool cut) {
  state.framesSinceCut = cut ? 1 : state.framesSinceCut + 1;
  if (state.freezeAtFrame > 0 && state.framesSinceCut >= state.freezeAtFrame) {
    state.frozen = true;
    state.freezeAtFrame = 0;
  }
}

void runStillFramesTo(ExplorerState& state, int frames) {
  if (state.cutPending || state.framesSinceCut > frames) {
    state.cutPending = true;
    state.framesSinceCut = 0;
  }
  if (state.framesSinceCut == frames) {  // already there
    state.frozen = true;
    state.freezeAtFrame = 0;
    return;
  }
  state.frozen = false;
  state.freezeAtFrame = frames;
}

int applyCompositionChanges(ExplorerState& state) {
  int rebuilt = 0;
  for (ViewportSlot& slot : state.slots) {
    if (!slot.viewport) continue;
    const Technique& t = slot.viewport->technique;
    if (!t.params.has(kLayoutParam) || t.params.choice(kLayoutParam) == t.layout->id()) continue;
    try {
      slot.viewport->setTechnique(recomposed(t));
      ++rebuilt;
    } catch (const std::exception& e) {  // keep the viewport drawing what it had
      slot.error = e.what();
      slot.viewport->technique.params.setFromString(kLayoutParam, t.layout->id());
    }
  }
  if (rebuilt > 0) applySelectedViews(state);  // the new layout may offer other views
  return rebuilt;
}

bool switchScene(ExplorerState& state, Renderer& renderer, const std::string& idOrPath) {
  std::unique_ptr<Scene> loaded;
  try {
    loaded = std::make_unique<Scene>(loadScene(idOrPath, state.assetsDir));
    renderer.setScene(*loaded);
  } catch (const std::exception& e) {
    // The renderer may have been handed the new scene before failing; give it back the old one.
    if (state.scene && renderer.scene() != state.scene.get()) {
      try {
        renderer.setScene(*state.scene);
      } catch (const std::exception&) {
      }
    }
    state.sceneError = e.what();
    return false;
  }
  // The accuracy panel's worker may be building a BVH from the old scene: stop it first.
  if (state.errorPanel) state.errorPanel->beforeSceneChange();
  state.scene = std::move(loaded);
  state.sceneLabel = idOrPath;
  state.sceneError.clear();
  state.sceneTime = 0.0;
  jumpToCamera(state, state.scene->cameras.front());
  return true;
}

glm::vec2 lightAngles(const Light& light) {
  const glm::vec3 toLight = -glm::normalize(light.direction);
  return glm::degrees(glm::vec2(std::atan2(toLight.x, toLight.z), std::asin(std::clamp(toLight.y, -1.0f, 1.0f))));
}

glm::vec3 directionFromLightAngles(float azimuthDeg, float elevationDeg) {
  const float az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
  return -glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

// Both setters end here: the accuracy panel's worker may be tracing under the old light (stop it
// first), and every accumulation's history belongs to the old light (a cut).
static void changeLight(ExplorerState& state, const std::function<void(Light&)>& change) {
  if (state.errorPanel) state.errorPanel->beforeSceneChange();
  change(state.scene->light);
  state.cutPending = true;
}

bool setLightPosition(ExplorerState& state, glm::vec3 position) {
  if (!state.scene || !state.scene->light.positional() || !std::isfinite(position.x) || !std::isfinite(position.y) ||
      !std::isfinite(position.z) || position == state.scene->light.position)
    return false;
  changeLight(state, [position](Light& l) { l.position = position; });
  return true;
}

bool setLightDirection(ExplorerState& state, glm::vec3 direction) {
  if (!state.scene || !std::isfinite(direction.x) || !std::isfinite(direction.y) || !std::isfinite(direction.z) ||
      !(glm::length(direction) > 1e-6f))
    return false;
  direction = glm::normalize(direction);
  if (glm::length(direction - state.scene->light.direction) < 1e-6f) return false;
  changeLight(state, [direction](Light& l) { l.direction = direction; });
  return true;
}

bool showLightInViews(ExplorerState& state, size_t k) {
  if (!state.scene || k >= state.scene->otherLights.size() || !state.scene->otherLights[k].shadow) return false;
  changeLight(state, [&state, k](Light& l) { std::swap(l, state.scene->otherLights[k]); });
  return true;
}

bool setOtherLightShadow(ExplorerState& state, size_t k, bool shadow) {
  if (!state.scene || k >= state.scene->otherLights.size() || state.scene->otherLights[k].shadow == shadow)
    return false;
  changeLight(state, [&state, k, shadow](Light&) { state.scene->otherLights[k].shadow = shadow; });
  return true;
}

void jumpToCamera(ExplorerState& state, const Camera& camera) {
  state.camera.jumpTo(camera, state.scene ? sceneDiagonal(*state.scene) : 10.0f);
  state.cameraName = camera.name;
  state.playingPath = nullptr;
  state.cutPending = true;
}

void startCameraPath(ExplorerState& state, const CameraPath& path) {
  state.playingPath = &path;
  state.pathTime = 0.0;
  state.cameraName = path.name;
  state.cutPending = true;  // jumping to the first key is a cut; following the path is not
}

void setViewportPreset(ExplorerState& state, int slot, const std::string& presetId) {
  ViewportSlot& s = state.slots.at(size_t(slot));
  try {
    Technique t = makeTechnique(presetId);
    if (s.viewport)
      s.viewport->setTechnique(std::move(t));
    else
      s.viewport = std::make_unique<Viewport>(std::move(t));
    s.error.clear();
    s.enlargedView.clear();
    s.title.clear();
  } catch (const std::exception& e) {
    s.error = e.what();
  }
}

void ensureViewportSlots(ExplorerState& state) {
  state.slots.resize(kMaxViewports);
  for (int i = 0; i < state.viewportCount; ++i) {
    if (state.slots[size_t(i)].viewport) continue;
    std::set<std::string> used;
    for (const ViewportSlot& s : state.slots)
      if (s.viewport) used.insert(s.viewport->technique.presetId);
    std::string preset = state.options.technique;
    for (const Preset& p : allPresets()) {
      if (!used.count(p.id)) {
        preset = p.id;
        break;
      }
    }
    setViewportPreset(state, i, preset);
  }
}

std::vector<Viewport*> shownViewports(const ExplorerState& state) {
  std::vector<Viewport*> result;
  for (int i = 0; i < state.viewportCount && i < int(state.slots.size()); ++i)
    if (state.slots[size_t(i)].viewport) result.push_back(state.slots[size_t(i)].viewport.get());
  return result;
}

std::vector<std::string> availableViewNames(const ExplorerState& state) {
  std::vector<std::string> names;
  auto addUnique = [&names](const std::string& n) {
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  };
  for (Viewport* vp : shownViewports(state))
    for (const std::string& n : vp->availableViews()) addUnique(n);
  if (!names.empty()) addUnique(ErrorPanel::kViewName);
  return names;
}

void applySelectedViews(ExplorerState& state) {
  for (int i = 0; i < state.viewportCount && i < int(state.slots.size()); ++i) {
    ViewportSlot& slot = state.slots[size_t(i)];
    if (!slot.viewport) continue;
    slot.viewport->shownViews.clear();
    for (const std::string& name : slot.viewport->availableViews())
      if (state.selectedViews.count(name)) slot.viewport->shownViews.push_back(name);
    if (!slot.enlargedView.empty() && !state.selectedViews.count(slot.enlargedView)) slot.enlargedView.clear();
  }
}

bool paramLinked(const ExplorerState& state, const std::string& key) {
  return state.linkAllParams || state.linkedParams.count(key) > 0;
}

int propagateLinkedParam(ExplorerState& state, int source, const std::string& key) {
  if (source < 0 || source >= int(state.slots.size()) || !state.slots[size_t(source)].viewport) return 0;
  const ParamSet& from = state.slots[size_t(source)].viewport->technique.params;
  if (!from.has(key)) return 0;
  const double value = from.get(key);
  int changed = 0;
  for (int i = 0; i < state.viewportCount && i < int(state.slots.size()); ++i) {
    ViewportSlot& slot = state.slots[size_t(i)];
    if (i == source || !slot.viewport || !slot.viewport->technique.params.has(key)) continue;
    ParamSet& to = slot.viewport->technique.params;
    if (to.get(key) == value) continue;
    try {
      to.set(key, value);
      ++changed;
    } catch (const ParamError& e) {
      slot.error = std::string("linked from viewport ") + std::to_string(source + 1) + ": " + e.what();
    }
  }
  return changed;
}

std::string cycleEnlargedView(ExplorerState& state, int step) {
  std::vector<std::string> cycle{""};
  for (const std::string& name : availableViewNames(state)) cycle.push_back(name);
  std::string current;
  if (!state.slots.empty()) current = state.slots.front().enlargedView;
  auto it = std::find(cycle.begin(), cycle.end(), current);
  const int n = int(cycle.size());
  const int index = it == cycle.end() ? 0 : int(it - cycle.begin());
  const std::string next = cycle[size_t(((index + step) % n + n) % n)];
  if (!next.empty()) state.selectedViews.insert(next);
  for (int i = 0; i < state.viewportCount && i < int(state.slots.size()); ++i) {
    ViewportSlot& slot = state.slots[size_t(i)];
    if (!slot.viewport) continue;
    const std::vector<std::string> offered = slot.viewport->availableViews();
    const bool has = next.empty() || next == ErrorPanel::kViewName ||
                     std::find(offered.begin(), offered.end(), next) != offered.end();
    slot.enlargedView = has ? next : "";
  }
  return next;
}

}  // namespace sl
