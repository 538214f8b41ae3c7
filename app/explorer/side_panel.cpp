#include "explorer/side_panel.h"

#include "explorer/error_panel.h"
#include "explorer/param_panel.h"
#include "explorer/screenshot.h"
#include "explorer/session_files.h"
#include "explorer/shortcuts.h"
#include "technique.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace sl {

namespace {

const ImVec4 kErrorColor(1.0f, 0.38f, 0.35f, 1.0f);
const ImVec4 kDimColor(0.65f, 0.65f, 0.68f, 1.0f);

void errorText(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

// Buttons laid out left to right, wrapping onto a new row when the next one would not fit.
// `first` starts a new flow (the previous item is then not a button of this row).
bool flowButton(const std::string& label, bool highlighted, bool& first) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float width = ImGui::CalcTextSize(label.c_str()).x + style.FramePadding.x * 2.0f;
  const float rowEnd = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (!first && ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <= rowEnd) ImGui::SameLine();
  first = false;
  if (highlighted) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
  const bool clicked = ImGui::Button(label.c_str());
  if (highlighted) ImGui::PopStyleColor();
  return clicked;
}

void drawStatusHeader(ExplorerState& state, Renderer& renderer, const ShaderLibrary& shaders) {
  const float ms = state.smoothedFrameMs;
  ImGui::Text("%.0f fps   %.1f ms/frame", ms > 0 ? 1000.0f / ms : 0.0f, ms);
  ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
  ImGui::TextWrapped("%s", glRendererName().c_str());
  ImGui::PopStyleColor();
  // Errors first: a shader typo must be noticed even with every section collapsed.
  // Several viewports can share a broken module; one line per distinct message is enough.
  // Where the last capture went (and settings trouble): here at the top, never below the fold.
  if (!state.statusLine.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.9f, 0.55f, 1.0f));
    ImGui::TextWrapped("%s", state.statusLine.c_str());
    ImGui::PopStyleColor();
  }
  if (!state.settingsMessage.empty()) errorText(state.settingsMessage);
  std::vector<std::string> errors = shaders.errors();
  std::sort(errors.begin(), errors.end());
  errors.erase(std::unique(errors.begin(), errors.end()), errors.end());
  if (!state.renderError.empty()) errors.push_back("render: " + state.renderError);
  if (errors.empty()) return;
  // A broken shared module can produce pages of messages: keep them in a scrolling box so the
  // rest of the panel stays reachable.
  const float wrapWidth = ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ScrollbarSize - 8.0f;
  float textHeight = 0.0f;
  for (const std::string& e : errors)
    textHeight += ImGui::CalcTextSize(e.c_str(), nullptr, false, wrapWidth).y + ImGui::GetStyle().ItemSpacing.y;
  const float boxHeight = std::min(textHeight + 12.0f, ImGui::GetIO().DisplaySize.y * 0.3f);
  ImGui::PushStyleColor(ImGuiCol_ChildBg, ImVec4(0.22f, 0.05f, 0.05f, 1.0f));
  ImGui::BeginChild("errors", ImVec2(0, boxHeight), true);
  for (const std::string& e : errors) errorText(e);
  ImGui::EndChild();
  ImGui::PopStyleColor();
}

// A scene of several lights: a row per other light, its shadow on or off, and a button that
// makes it the light the views, the drag fields above and the accuracy panel show.
void drawOtherLights(ExplorerState& state) {
  if (!state.scene || state.scene->otherLights.empty()) return;
  static const char* const kTypes[] = {"directional", "spot", "point"};
  ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
  ImGui::Text("%zu lights; views and fields: light 1 (%s)", state.scene->otherLights.size() + 1,
              kTypes[int(state.scene->light.type)]);
  ImGui::PopStyleColor();
  for (size_t k = 0; k < state.scene->otherLights.size(); ++k) {
    const Light& l = state.scene->otherLights[k];
    ImGui::PushID(int(k));
    bool shadow = l.shadow;
    if (ImGui::Checkbox("##shadow", &shadow)) setOtherLightShadow(state, k, shadow);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("shadowed: the technique makes maps for this light too");
    ImGui::SameLine();
    ImGui::BeginDisabled(!l.shadow);
    if (ImGui::SmallButton("show")) showLightInViews(state, k);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
      ImGui::SetTooltip("make this light the one the debug views, drag fields and accuracy panel show");
    ImGui::SameLine();
    if (l.positional())
      ImGui::Text("light %zu %s at %.1f %.1f %.1f", k + 2, kTypes[int(l.type)], l.position.x, l.position.y,
                  l.position.z);
    else
      ImGui::Text("light %zu %s", k + 2, kTypes[int(l.type)]);
    ImGui::PopID();
  }
}

void drawScenePanel(ExplorerState& state, Renderer& renderer) {
  if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##scene", state.sceneLabel.c_str())) {
    for (const std::string& id : state.sceneIds)
      if (ImGui::Selectable(id.c_str(), id == state.sceneLabel) && id != state.sceneLabel)
        switchScene(state, renderer, id);
    ImGui::EndCombo();
  }
  ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Load").x - ImGui::GetStyle().FramePadding.x * 2 -
                          ImGui::GetStyle().ItemSpacing.x);
  const bool entered = ImGui::InputTextWithHint("##scenePath", ".json / .gltf / .glb path", &state.scenePathInput,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button("Load") || entered) && !state.scenePathInput.empty())
    switchScene(state, renderer, state.scenePathInput);
  if (!state.sceneError.empty()) errorText(state.sceneError);
  if (state.scene) {
    ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
    ImGui::Text("%zu triangles, %zu instances", state.scene->triangleCount(), state.scene->instances.size());
    ImGui::PopStyleColor();
  }
  if (state.scene && state.scene->light.type == Light::Type::Point) {
    // A point light has a position and no direction: drag where it is.
    glm::vec3 position = state.scene->light.position;
    const float speed = 0.002f * sceneDiagonal(*state.scene);
    const float third = (ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().ItemSpacing.x) / 3.0f;
    static const char* const kAxes[3] = {"light x %.2f", "y %.2f", "z %.2f"};
    bool moved = false;
    for (int axis = 0; axis < 3; ++axis) {
      if (axis > 0) ImGui::SameLine();
      ImGui::PushID(axis);
      ImGui::SetNextItemWidth(third);
      moved |= ImGui::DragFloat("##lightPosition", &position[axis], speed, 0.0f, 0.0f, kAxes[axis]);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("point light position; moving it resets accumulated history and references");
      ImGui::PopID();
    }
    if (moved) setLightPosition(state, position);
  } else if (state.scene) {
    // Dragging the light is a cut for accumulations (their history was gathered under the old
    // light) and drops the accuracy panel's references.
    glm::vec2 angles = lightAngles(state.scene->light);
    const float half = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) * 0.5f;
    ImGui::SetNextItemWidth(half);
    bool changed = ImGui::SliderFloat("##azimuth", &angles.x, -180.0f, 180.0f, "light az %.0f deg");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(half);
    changed |= ImGui::SliderFloat("##elevation", &angles.y, -90.0f, 90.0f, "elev %.0f deg");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("direction towards the light; changing it resets accumulated history and references");
    if (changed) setLightDirection(state, directionFromLightAngles(angles.x, angles.y));
  }
  drawOtherLights(state);
  ImGui::Checkbox("Pause time (P)", &state.paused);
  ImGui::SameLine();
  ImGui::Text("t = %.2f s", state.sceneTime);
  ImGui::Checkbox("Freeze frames (F)", &state.frozen);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("render no new frame; Step renders one (watch pixel-correct converge frame by frame)");
  ImGui::SameLine();
  ImGui::BeginDisabled(!state.frozen);
  if (ImGui::Button("Step (N)")) state.stepRequested = true;
  ImGui::EndDisabled();
}

void drawCameraPanel(ExplorerState& state) {
  if (!ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen) || !state.scene) return;
  bool first = true;
  for (const Camera& c : state.scene->cameras) {
    ImGui::PushID(&c);
    if (flowButton(c.name.empty() ? "camera" : c.name, !state.playingPath && c.name == state.cameraName, first))
      jumpToCamera(state, c);
    ImGui::PopID();
  }
  if (!state.scene->paths.empty()) {
    ImGui::TextUnformatted("Paths:");
    first = true;
    for (const CameraPath& p : state.scene->paths) {
      ImGui::PushID(&p);
      if (flowButton("> " + p.name, state.playingPath == &p, first)) {
        if (state.playingPath == &p)
          state.playingPath = nullptr;  // second click stops, camera stays where it is
        else
          startCameraPath(state, p);
      }
      ImGui::PopID();
    }
  }
  // Speed as a share of the scene's diagonal per second, so it suits any scene size.
  float factor = state.camera.speedFactor() * 100.0f;
  char speedLabel[64];
  std::snprintf(speedLabel, sizeof speedLabel, "%%.1f%%%% of scene/s (%.2g units/s)", state.camera.speed());
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Help (F1)").x -
                          ImGui::GetStyle().FramePadding.x * 2 - ImGui::GetStyle().ItemSpacing.x);
  if (ImGui::SliderFloat("##speed", &factor, FlyCamera::kMinSpeedFactor * 100.0f, FlyCamera::kMaxSpeedFactor * 100.0f,
                         speedLabel, ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
    state.camera.setSpeedFactor(factor / 100.0f);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("camera speed: WASD/QE move, Shift 4x, the wheel over a viewport changes it too");
  ImGui::SameLine();
  if (ImGui::Button("Help (F1)")) state.showHelp = !state.showHelp;
}

void drawViewportPanels(ExplorerState& state) {
  ImGui::Separator();
  ImGui::TextUnformatted("Viewports");
  for (int n = 1; n <= kMaxViewports; ++n) {
    ImGui::SameLine();
    if (ImGui::RadioButton(std::to_string(n).c_str(), state.viewportCount == n)) state.viewportCount = n;
  }
  ensureViewportSlots(state);
  if (state.viewportCount > 1) {
    // Beside the radio buttons when it fits (a large UI scale moves it to its own row).
    const float needed =
        ImGui::GetFrameHeight() + ImGui::CalcTextSize("link all").x + ImGui::GetStyle().ItemSpacing.x * 2;
    if (ImGui::GetItemRectMax().x + needed <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x)
      ImGui::SameLine();
    ImGui::Checkbox("link all", &state.linkAllParams);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Every parameter edit goes to every viewport whose technique has that parameter.\n"
          "Or link single parameters with the button before each one.");
  }

  for (int i = 0; i < state.viewportCount; ++i) {
    ViewportSlot& slot = state.slots[size_t(i)];
    if (!slot.viewport) {
      if (!slot.error.empty()) errorText(slot.error);
      continue;
    }
    Technique& technique = slot.viewport->technique;
    ImGui::PushID(i);
    const std::string header = std::to_string(i + 1) + ": " + technique.label() + "###viewport";
    if (ImGui::CollapsingHeader(header.c_str(), i == 0 ? ImGuiTreeNodeFlags_DefaultOpen : 0)) {
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
      if (ImGui::BeginCombo("preset", technique.presetId.c_str())) {
        for (const Preset& p : allPresets()) {
          if (ImGui::Selectable(p.id.c_str(), p.id == technique.presetId) && p.id != technique.presetId)
            setViewportPreset(state, i, p.id);
          if (ImGui::IsItemHovered() && !p.help.empty()) ImGui::SetTooltip("%s", p.help.c_str());
        }
        ImGui::EndCombo();
      }
      ImGui::SameLine();
      if (ImGui::SmallButton("Reset")) setViewportPreset(state, i, technique.presetId);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back to the preset's values");
      // Every part's status and the several lights' (wrapped: the tile header has room only for
      // its start).
      const std::string status = slot.viewport->status();
      if (!status.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, kDimColor);
        ImGui::TextWrapped("%s", status.c_str());
        ImGui::PopStyleColor();
      }
      // setViewportPreset may have replaced the technique: read it again.
      ParamLinks links{state.viewportCount > 1 ? &state.linkedParams : nullptr, state.linkAllParams, {}};
      drawParamPanel(slot.viewport->technique.params, slot.error, &links,
                     paramsWithoutEffect(slot.viewport->technique.params, state.scene.get()));
      for (const std::string& key : links.changed)
        if (paramLinked(state, key)) propagateLinkedParam(state, i, key);
      if (!slot.error.empty()) errorText(slot.error);
    }
    ImGui::PopID();
  }
}

void drawDebugViewPanel(ExplorerState& state) {
  if (!ImGui::CollapsingHeader("Debug views")) return;
  const std::vector<std::string> names = availableViewNames(state);
  if (names.empty()) ImGui::TextDisabled("(none offered by these techniques)");
  ImGui::Checkbox("Colour keys (K)", &state.showColourKeys);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("what each heat-map view's colours mean, drawn over its image");
  // Two columns of checkboxes keep the list short enough to stay on screen.
  ImGui::Columns(2, "views", false);
  for (const std::string& name : names) {
    bool selected = state.selectedViews.count(name) > 0;
    if (ImGui::Checkbox(name.c_str(), &selected)) {
      if (selected)
        state.selectedViews.insert(name);
      else
        state.selectedViews.erase(name);
    }
    if (name == ErrorPanel::kViewName && ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Difference to the ray-traced reference (needs a resting camera):\n"
          "grey = agrees, orange = false shadow, blue = false light, magenta = NaN.");
    ImGui::NextColumn();
  }
  ImGui::Columns(1);
}

void drawTimingPanel(Renderer& renderer) {
  if (!ImGui::CollapsingHeader("Timings", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const FrameStats& stats = renderer.stats();
  ImGui::Checkbox("Time passes", &renderer.timePasses);
  ImGui::SameLine();
  ImGui::TextDisabled("timer: %s", stats.timer.empty() ? "-" : stats.timer.c_str());
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "gpu-query: GL timer queries, the newest frame's that have arrived (a frame or two old: "
        "the CPU does not wait for the GPU).\ncpu-fence: glFinish around each pass "
        "(software GL, where queries measure nothing); slows the frame down.");
  double total = 0.0;
  for (const PassTiming& p : stats.passes) total += p.ms;
  ImGui::Text("frame %.2f ms, passes %.2f ms", stats.frameMs, total);
  const double scale = std::max({stats.frameMs, total, 1e-6});
  const float nameWidth = ImGui::GetContentRegionAvail().x * 0.45f;
  for (const PassTiming& p : stats.passes) {
    ImGui::TextUnformatted(p.name.c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p.name.c_str());
    ImGui::SameLine(nameWidth);
    char overlay[32];
    std::snprintf(overlay, sizeof overlay, "%.2f ms", p.ms);
    ImGui::ProgressBar(float(p.ms / scale), ImVec2(-1, ImGui::GetTextLineHeight()), overlay);
  }
}

void drawToolsPanel(ExplorerState& state) {
  ImGui::Separator();
  ImGui::Checkbox("Magnifier (hold M)", &state.magnifierPinned);
  ImGui::Checkbox("Visibility plot (hold V)", &state.plotPinned);
  ImGui::Checkbox("dp/ds plot (perspective aliasing)", &state.showDpdsPlot);
  // UI size for the room: fonts are rebuilt at the new size (Ctrl+= / Ctrl+-).
  ImGui::Text("UI size %.0f %%", state.uiScale * 100.0f);
  ImGui::SameLine();
  if (ImGui::SmallButton(" - ")) state.uiScale = steppedUiScale(state.uiScale, -1);
  ImGui::SameLine();
  if (ImGui::SmallButton(" + ")) state.uiScale = steppedUiScale(state.uiScale, 1);
  ImGui::SameLine();
  ImGui::TextDisabled("Ctrl + = / Ctrl + -");

  ImGui::TextUnformatted("Save to folder:");
  if (state.screenshotDir.empty()) state.screenshotDir = defaultScreenshotDir();
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##shotdir", &state.screenshotDir);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("created when something is saved; kept between runs");
  if (ImGui::Button("Window (F12)")) state.screenshotRequested = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the whole window, panels included");
  ImGui::SameLine();
  if (ImGui::Button("Viewport images")) state.viewportShotsRequested = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("each viewport's image alone, at its rendered size, no UI (Shift + F12)");
  ImGui::SameLine();
  if (ImGui::Button("Table + chart")) exportAccuracy(state);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the accuracy table as CSV and the error-vs-time chart as SVG");
  if (!state.statusLine.empty()) ImGui::TextWrapped("%s", state.statusLine.c_str());
}

}  // namespace

void drawSidePanel(ExplorerState& state, Renderer& renderer, const ShaderLibrary& shaders) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(std::min(sidePanelWidth(state.uiScale, display.x), display.x), display.y));
  // No background: the window is cleared to the same colour, and a blended full-height
  // rectangle is a measurable cost on a software rasterizer.
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBackground;
  ImGui::Begin("shadowlab explorer", nullptr, flags);
  drawStatusHeader(state, renderer, shaders);
  drawScenePanel(state, renderer);
  drawCameraPanel(state);
  drawViewportPanels(state);
  drawDebugViewPanel(state);
  drawTimingPanel(renderer);
  if (state.errorPanel) state.errorPanel->drawPanel(state);
  drawToolsPanel(state);
  ImGui::End();
}

}  // namespace sl
