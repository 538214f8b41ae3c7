// Lecture tours in the explorer (--tour T.json, docs/tour-format.md): each step sets the scene,
// camera, light, viewports and debug views; Right/Down/PageDown go to the next step and
// Left/Up/PageUp to the previous one (presenter clickers send PageUp/PageDown), F5 toggles
// presenter mode (no side panel, large text, viewports filling the window). The caption sits in
// a strip under the viewports. A step with several still-frame counts ("frames": [1, 20, 40,
// 60]) is played like a slide with builds: it freezes after 1 frame, and each "next" renders on
// to the next count before the next step comes; "previous" goes back a count (re-rendered from a
// cut). A step's plot is made when the step is shown and drawn in a window beside the caption.
#pragma once

#include "explorer/explorer_state.h"
#include "plot/plot.h"
#include "tour/tour.h"

#include <imgui.h>

#include <optional>
#include <string>

namespace sl {

class Renderer;

// The height of the caption strip a step needs at `width` with the current font: its title row,
// the still-frame row when `staged`, the viewport names and the caption, wrapped.
float captionStripHeight(const TourStep& s, float width, bool staged);
constexpr float kPresenterScale = 1.75f;  // presenter mode's text: readable from the back of a lecture hall
// The caption strip grows to at most this share of the window's height; beyond, it scrolls.
inline constexpr float kCaptionMaxShare = 0.55f;

class TourPlayer {
 public:
  // Loads the tour and shows step `firstStep` (1-based); false after printing why not.
  bool start(ExplorerState& state, Renderer& renderer, const std::string& path, int firstStep, bool presenter);
  bool active() const { return tour_.has_value(); }
  bool presenter() const { return active() && presenter_; }
  size_t step() const { return step_; }
  // Keys (ignored while a text field has the keyboard); call before the panels are drawn.
  void handleKeys(ExplorerState& state, Renderer& renderer);
  // Height the caption strip takes from the bottom of the main area (0 without a tour).
  // area: the window less the side panel. What the step's text needs at that width (every line,
  // the caption wrapped), at most 55 % of its height (beyond it the strip scrolls).
  float captionHeight(ImVec2 area) const;
  float captionNeeded(float width) const;
  // The caption strip (title, caption, step buttons) over the bottom `captionHeight()` of the area.
  void drawCaption(ExplorerState& state, Renderer& renderer, ImVec2 areaMin, ImVec2 areaSize);
  // The step's plot window (nothing for a step without a plot), at the top right of the area.
  // Width of the strip the step's plot takes on the right of `area` (the window less the side
  // panel; 0 without a plot): the viewports are laid out beside it, so the plot hides none.
  float plotStripWidth(ImVec2 area) const;
  // The plot window inside its strip (areaMin, areaSize: the strip above the caption).
  void drawPlot(ImVec2 areaMin, ImVec2 areaSize);
  // Shows step `index` (0-based); a step that fails to apply keeps the window with its message.
  void show(ExplorerState& state, Renderer& renderer, size_t index);
  // Forward and back through the steps and, within a step, its still-frame counts.
  void next(ExplorerState& state, Renderer& renderer);
  void previous(ExplorerState& state, Renderer& renderer);
  // Index into the current step's frames of the count shown (0 for a step with one).
  size_t frameStage() const { return frameStage_; }
  int stageFrames() const;  // the still-frame count of that stage

 private:
  void setPresenter(bool on);
  bool staged() const;  // the current step has more than one frame count, or one above 1
  void showFrameStage(ExplorerState& state, size_t stage);
  void drawFrameButtons(ExplorerState& state);
  void makePlot(ExplorerState& state, Renderer& renderer);
  std::optional<Tour> tour_;
  size_t step_ = 0;
  size_t frameStage_ = 0;
  Plot plot_;
  std::string plotError_;
  bool presenter_ = false;
  std::string error_;  // why the current step could not be shown
};

}  // namespace sl
