// TourPlayer (see tour_player.h): applies tour steps to the explorer's state with the same
// actions the side panel uses, so a step looks as if the lecturer had clicked it together.
#include "explorer/tour_player.h"

#include "explorer/plot_window.h"
#include "explorer/shortcuts.h"
#include "render/renderer.h"
#include "tour/step_plot.h"
#include "technique.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace sl {
namespace {

// The frame a step's plot is made at (the figures' default panel; the plot's pixel is its centre).
constexpr int kPlotFrameWidth = 480, kPlotFrameHeight = 270;

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
    slot.title = findPreset(v.technique) ? v.label : v.technique + " (not built yet: standard shown)";
    state.selectedViews.insert(v.views.begin(), v.views.end());
  }
  state.viewportCount = viewportCountFor(s.viewports.size());
  ensureViewportSlots(state);
  applySelectedViews(state);
  // A step may show one view large in a tile instead of thumbnails too small to read (#23).
  for (size_t i = 0; i < s.viewports.size(); ++i) state.slots[i].enlargedView = s.viewports[i].enlarged;
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
  frameStage_ = 0;
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
    state.freezeAtFrame = 0;
    state.cutPending = true;
    if (staged()) showFrameStage(state, 0);
  } catch (const std::exception& e) {
    error_ = e.what();
  }
  makePlot(state, renderer);
}

int TourPlayer::stageFrames() const { return tour_ ? tour_->steps[step_].frames[frameStage_] : 0; }

bool TourPlayer::staged() const {
  if (!tour_) return false;
  const std::vector<int>& frames = tour_->steps[step_].frames;
  return frames.size() > 1 || (frames.size() == 1 && frames[0] > 1);
}

void TourPlayer::showFrameStage(ExplorerState& state, size_t stage) {
  frameStage_ = std::min(stage, tour_->steps[step_].frames.size() - 1);
  runStillFramesTo(state, tour_->steps[step_].frames[frameStage_]);
}

void TourPlayer::next(ExplorerState& state, Renderer& renderer) {
  if (!tour_) return;
  if (staged() && frameStage_ + 1 < tour_->steps[step_].frames.size())
    showFrameStage(state, frameStage_ + 1);
  else if (step_ + 1 < tour_->steps.size())
    show(state, renderer, step_ + 1);
}

void TourPlayer::previous(ExplorerState& state, Renderer& renderer) {
  if (!tour_) return;
  if (staged() && frameStage_ > 0)
    showFrameStage(state, frameStage_ - 1);
  else if (step_ > 0)
    show(state, renderer, step_ - 1);
}

// The plot is made once, with the step's camera (as the figure makes it); a visibility plot
// renders a frame per technique, a dp/ds plot is computed on the CPU.
void TourPlayer::makePlot(ExplorerState& state, Renderer& renderer) {
  plot_ = {};
  plotError_.clear();
  const TourStep& s = tour_->steps[step_];
  if (s.plot.kind == TourPlot::Kind::None || !error_.empty() || !state.scene) return;
  try {
    plot_ = stepPlot(*tour_, step_, *state.scene, stepCamera(*tour_, step_, *state.scene), renderer.shaders(),
                     kPlotFrameWidth, kPlotFrameHeight);
  } catch (const std::exception& e) {
    plotError_ = e.what();
  }
}

void TourPlayer::handleKeys(ExplorerState& state, Renderer& renderer) {
  if (!tour_ || ImGui::GetIO().WantTextInput) return;
  // Presses recorded from GLFW (explorer/shortcuts.h): a clicker's short tap is never lost.
  const bool next = keyPressed(GLFW_KEY_RIGHT) || keyPressed(GLFW_KEY_DOWN) || keyPressed(GLFW_KEY_PAGE_DOWN);
  const bool previous = keyPressed(GLFW_KEY_LEFT) || keyPressed(GLFW_KEY_UP) || keyPressed(GLFW_KEY_PAGE_UP);
  if (next) this->next(state, renderer);
  if (previous) this->previous(state, renderer);
  if (keyPressed(GLFW_KEY_F5)) setPresenter(!presenter_);
}

namespace {
float wrappedHeight(const std::string& text, float width) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float wrap = std::max(width - 2.0f * style.WindowPadding.x, 1.0f);
  return ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap).y + style.ItemSpacing.y;
}
}  // namespace

float captionStripHeight(const TourStep& s, float width, bool staged) {
  float h = ImGui::GetFrameHeightWithSpacing();  // step buttons, number and title
  if (staged) h += ImGui::GetFrameHeightWithSpacing();
  if (const std::string labels = viewportLabels(s); !labels.empty()) h += wrappedHeight(labels, width);
  return h + wrappedHeight(s.shownCaption(), width) + 2.0f * ImGui::GetStyle().WindowPadding.y;
}

float TourPlayer::captionNeeded(float width) const {
  if (!tour_) return 0.0f;
  float h = captionStripHeight(tour_->steps[step_], width, staged());
  if (!error_.empty()) h += wrappedHeight(error_, width);
  if (!plotError_.empty()) h += wrappedHeight(plotError_, width);
  return h;
}

float TourPlayer::captionHeight(ImVec2 area) const {
  return std::min(captionNeeded(area.x), std::floor(area.y * kCaptionMaxShare));
}

void TourPlayer::drawCaption(ExplorerState& state, Renderer& renderer, ImVec2 areaMin, ImVec2 areaSize) {
  if (!tour_) return;
  const float h = captionHeight(areaSize);
  ImGui::SetNextWindowPos(ImVec2(areaMin.x, areaMin.y + areaSize.y - h));
  ImGui::SetNextWindowSize(ImVec2(areaSize.x, h));
  // A scroll bar only where the text is taller than the strip may grow.
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing;
  ImGui::Begin("##tour caption", nullptr, flags);
  const TourStep& s = tour_->steps[step_];
  if (!presenter_) {
    if (ImGui::ArrowButton("##previous", ImGuiDir_Left)) previous(state, renderer);
    ImGui::SameLine();
    if (ImGui::ArrowButton("##next", ImGuiDir_Right)) next(state, renderer);
    ImGui::SameLine();
    bool p = presenter_;
    if (ImGui::Checkbox("presenter (F5)", &p)) setPresenter(p);
    ImGui::SameLine();
  }
  ImGui::TextDisabled("%zu/%zu", step_ + 1, tour_->steps.size());
  ImGui::SameLine();
  ImGui::TextUnformatted(s.title.c_str());
  if (staged()) drawFrameButtons(state);
  ImGui::PushTextWrapPos(0.0f);  // every line wraps as captionNeeded measured it
  if (const std::string labels = viewportLabels(s); !labels.empty()) ImGui::TextDisabled("%s", labels.c_str());
  if (!s.built()) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
  ImGui::TextWrapped("%s", s.shownCaption().c_str());
  if (!s.built()) ImGui::PopStyleColor();
  if (!error_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", error_.c_str());
  if (!plotError_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", plotError_.c_str());
  ImGui::PopTextWrapPos();
  ImGui::End();
}

// "frames: [1] 20 40 60 · frame 7": the step's still-frame counts as buttons (the shown one
// highlighted) and the frames rendered since the cut.
void TourPlayer::drawFrameButtons(ExplorerState& state) {
  const std::vector<int>& frames = tour_->steps[step_].frames;
  ImGui::TextDisabled("still frames (next / previous step through them):");
  for (size_t i = 0; i < frames.size(); ++i) {
    ImGui::SameLine();
    const bool current = i == frameStage_;
    if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    ImGui::PushID(int(i));
    if (ImGui::SmallButton(std::to_string(frames[i]).c_str())) showFrameStage(state, i);
    ImGui::PopID();
    if (current) ImGui::PopStyleColor();
  }
  ImGui::SameLine();
  ImGui::TextDisabled("(now %d%s)", state.framesSinceCut, state.frozen ? ", frozen" : "");
}

float TourPlayer::plotStripWidth(ImVec2 area) const {
  if (!tour_ || plot_.empty()) return 0.0f;
  const float line = ImGui::GetTextLineHeight();
  return std::floor(std::min(line * 34.0f, area.x * 0.4f) + ImGui::GetStyle().WindowPadding.x * 2.0f + line);
}

void TourPlayer::drawPlot(ImVec2 areaMin, ImVec2 areaSize) {
  if (!tour_ || plot_.empty() || areaSize.x <= 0.0f) return;
  const float line = ImGui::GetTextLineHeight();
  const float padding = ImGui::GetStyle().WindowPadding.x;
  const ImVec2 size(std::max(areaSize.x - 2.0f * padding - line, line),
                    std::max(std::min(line * 15.0f, areaSize.y * 0.6f), line));
  ImGui::SetNextWindowPos(ImVec2(areaMin.x + line * 0.5f, areaMin.y + line * 0.5f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.92f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing;
  // The plot's title (a visibility plot's names the pixel and its map uv) is wrapped inside the
  // window: as the title bar it was cut at the strip's width.
  if (ImGui::Begin("step plot###tour plot", nullptr, flags)) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + size.x);
    ImGui::TextWrapped("%s", plot_.title.c_str());
    ImGui::PopTextWrapPos();
    drawPlotWidget(plot_, size);
    drawPlotCaption(plot_.x.label + "; y: " + plot_.y.label + (plot_.note.empty() ? "" : "; " + plot_.note), size.x);
  }
  ImGui::End();
}

}  // namespace sl
