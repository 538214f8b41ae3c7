// TourPlayer (see tour_player.h): applies tour steps to the explorer's state with the same
// actions the side panel uses, so a step looks as if the lecturer had clicked it together.
#include "explorer/tour_player.h"

#include "render/renderer.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace sl {
namespace {

constexpr float kPresenterScale = 1.75f;  // text readable from the back of a lecture hall
constexpr float kCaptionLines = 5.0f;     // title, panel names, three lines of caption

// ImGui 1.86 indexes io.KeysDown by the GLFW key codes the backend receives.
constexpr int kKeyRight = 262, kKeyLeft = 263, kKeyDown = 264, kKeyUp = 265, kKeyPageUp = 266, kKeyPageDown = 267,
              kKeyF5 = 294;

void applyViewports(ExplorerState& state, const TourStep& s) {
  state.slots.resize(kMaxViewports);
  state.selectedViews.clear();
  for (size_t i = 0; i < s.viewports.size(); ++i) {
    const TourViewport& v = s.viewports[i];
    // A technique that is not built yet shows the standard map; the caption says so.
    Technique t = findPreset(v.technique) ? makeTechnique(v.technique, v.overrides) : makeTechnique("standard");
    ViewportSlot& slot = state.slots[i];
    if (slot.viewport)
      slot.viewport->setTechnique(std::move(t));
    else
      slot.viewport = std::make_unique<Viewport>(std::move(t));
    slot.error.clear();
    slot.enlargedView.clear();
    state.selectedViews.insert(v.views.begin(), v.views.end());
  }
  const size_t n = s.viewports.size();
  state.viewportCount = n <= 1 ? 1 : n == 2 ? 2 : 4;
  ensureViewportSlots(state);
  applySelectedViews(state);
}

// Captions use Greek letters, arrows and maths (α, →, ∞, √) that the explorer's font lacks: merge
// those ranges of the same font in before the backend builds the font texture (first frame).
void addCaptionGlyphs() {
  static const ImWchar ranges[] = {0x0370, 0x03FF, 0x2010, 0x206F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};
  ImFontAtlas* atlas = ImGui::GetIO().Fonts;
  if (atlas->IsBuilt() || atlas->ConfigData.empty()) return;
  const ImFontConfig& base = atlas->ConfigData.back();
  if (base.FontDataOwnedByAtlas == false || base.FontData == nullptr || base.SizePixels <= 0.0f) return;
  for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf"}) {
    if (!std::filesystem::exists(path)) continue;
    ImFontConfig cfg;
    cfg.MergeMode = true;
    atlas->AddFontFromFileTTF(path, base.SizePixels, &cfg, ranges);
    return;
  }
}

// "1: n = z_n   2: n_opt": the tour's panel names and stand-ins, which the tiles' headers do not show.
std::string viewportLabels(const TourStep& s) {
  std::string out;
  for (size_t i = 0; i < s.viewports.size(); ++i) {
    const TourViewport& v = s.viewports[i];
    std::string name = v.label;
    if (!findPreset(v.technique)) name = v.technique + " (not built yet: standard shown)";
    if (!name.empty()) out += (out.empty() ? "" : "   ") + std::to_string(i + 1) + ": " + name;
  }
  return out;
}

}  // namespace

bool TourPlayer::start(ExplorerState& state, Renderer& renderer, const std::string& path, int firstStep,
                       bool presenter) {
  try {
    tour_ = loadTour(path);
  } catch (const std::exception& e) {
    std::cerr << "shadowlab: " << e.what() << "\n";
    return false;
  }
  if (firstStep < 1 || firstStep > static_cast<int>(tour_->steps.size())) {
    std::cerr << "shadowlab: --tour-step " << firstStep << ": " << path << " has steps 1 to " << tour_->steps.size()
              << "\n";
    return false;
  }
  addCaptionGlyphs();
  setPresenter(presenter);
  show(state, renderer, size_t(firstStep - 1));
  return true;
}

void TourPlayer::setPresenter(bool on) {
  presenter_ = on;
  ImGui::GetIO().FontGlobalScale = on ? kPresenterScale : 1.0f;
}

void TourPlayer::show(ExplorerState& state, Renderer& renderer, size_t index) {
  if (!tour_) return;
  step_ = std::min(index, tour_->steps.size() - 1);
  const TourStep& s = tour_->steps[step_];
  error_.clear();
  try {
    // Always reloaded: the step's light must not inherit the previous step's.
    if (!switchScene(state, renderer, stepScenePath(*tour_, step_))) {
      error_ = state.sceneError;
      return;
    }
    if (s.setLight) setLightDirection(state, directionFromLightAngles(s.lightAngles.x, s.lightAngles.y));
    if (s.camera.kind == TourCamera::Kind::Path) {
      if (const CameraPath* p = state.scene->findPath(s.camera.name)) startCameraPath(state, *p);
    }
    if (!state.playingPath) jumpToCamera(state, stepCamera(*tour_, step_, *state.scene));
    applyViewports(state, s);
    state.frozen = false;
    state.cutPending = true;
  } catch (const std::exception& e) {
    error_ = e.what();
  }
}

void TourPlayer::handleKeys(ExplorerState& state, Renderer& renderer) {
  if (!tour_ || ImGui::GetIO().WantTextInput) return;
  const bool next =
      ImGui::IsKeyPressed(kKeyRight) || ImGui::IsKeyPressed(kKeyDown) || ImGui::IsKeyPressed(kKeyPageDown);
  const bool previous = ImGui::IsKeyPressed(kKeyLeft) || ImGui::IsKeyPressed(kKeyUp) || ImGui::IsKeyPressed(kKeyPageUp);
  if (next && step_ + 1 < tour_->steps.size()) show(state, renderer, step_ + 1);
  if (previous && step_ > 0) show(state, renderer, step_ - 1);
  if (ImGui::IsKeyPressed(kKeyF5, false)) setPresenter(!presenter_);
}

float TourPlayer::captionHeight() const {
  if (!tour_) return 0.0f;
  const ImGuiStyle& style = ImGui::GetStyle();
  return ImGui::GetFontSize() * kCaptionLines * 1.25f + style.WindowPadding.y * 2.0f;
}

void TourPlayer::drawCaption(ExplorerState& state, Renderer& renderer, ImVec2 areaMin, ImVec2 areaSize) {
  if (!tour_) return;
  const float h = captionHeight();
  ImGui::SetNextWindowPos(ImVec2(areaMin.x, areaMin.y + areaSize.y - h));
  ImGui::SetNextWindowSize(ImVec2(areaSize.x, h));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing;
  ImGui::Begin("##tour caption", nullptr, flags);
  const TourStep& s = tour_->steps[step_];
  if (!presenter_) {
    if (ImGui::ArrowButton("##previous", ImGuiDir_Left) && step_ > 0) show(state, renderer, step_ - 1);
    ImGui::SameLine();
    if (ImGui::ArrowButton("##next", ImGuiDir_Right) && step_ + 1 < tour_->steps.size())
      show(state, renderer, step_ + 1);
    ImGui::SameLine();
    bool p = presenter_;
    if (ImGui::Checkbox("presenter (F5)", &p)) setPresenter(p);
    ImGui::SameLine();
  }
  ImGui::TextDisabled("%zu/%zu", step_ + 1, tour_->steps.size());
  ImGui::SameLine();
  ImGui::TextUnformatted(s.title.c_str());
  if (const std::string labels = viewportLabels(s); !labels.empty()) ImGui::TextDisabled("%s", labels.c_str());
  if (!s.built()) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
  ImGui::TextWrapped("%s", s.shownCaption().c_str());
  if (!s.built()) ImGui::PopStyleColor();
  if (!error_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", error_.c_str());
  ImGui::End();
}

}  // namespace sl
