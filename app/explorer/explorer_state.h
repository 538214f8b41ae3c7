// Everything the explorer window remembers between frames, and the actions the panels take
// on it. Kept free of GLFW so panels and the app loop share one vocabulary.
#pragma once

#include "explorer/explorer.h"
#include "explorer/fly_camera.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "technique.h"

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace sl {

class ErrorPanel;

constexpr int kMaxViewports = 4;
// The viewports shown for n techniques: exactly n (1 to 4); three sit side by side, as a
// caption's "left, middle, right" reads, four as 2x2 (layoutMainArea).
inline int viewportCountFor(size_t n) { return n <= 1 ? 1 : n >= size_t(kMaxViewports) ? kMaxViewports : int(n); }

struct ViewportSlot {
  std::unique_ptr<Viewport> viewport;
  std::string enlargedView;  // debug view shown in the big image instead of the colour ("" = colour)
  std::string error;         // last rejected parameter value or preset
  std::string title;         // a tour's name for it ("n = z_n"), shown in its header ("" = the technique's)
};

struct ExplorerState {
  ExplorerOptions options;
  std::string shaderDir, assetsDir;

  // Scene. The renderer keeps a pointer to it, so it is only ever replaced, never moved.
  std::vector<std::string> sceneIds;
  std::unique_ptr<Scene> scene;
  std::string sceneLabel;      // builtin id or the path it was loaded from
  std::string scenePathInput;  // text field for loading a file
  std::string sceneError;      // last failed load; the previous scene stays
  double sceneTime = 0.0;
  bool paused = false;
  // Frame stepping for teaching: while frozen no frame is rendered (the images stay), and each
  // step renders exactly one, so a lecturer can watch accumulating techniques converge.
  bool frozen = false;
  bool stepRequested = false;
  // Still frames rendered since the last cut, and the count at which to freeze (0 = none): a
  // tour step's "frames" [1, 20, 40, 60] stops at each count in turn.
  int framesSinceCut = 0;
  int freezeAtFrame = 0;

  // Camera. `cutPending` tells the renderer that history from earlier frames is invalid.
  FlyCamera camera;
  std::string cameraName;  // scene camera last jumped to (for the panel)
  const CameraPath* playingPath = nullptr;
  double pathTime = 0.0;
  bool cutPending = true;
  bool looking = false;  // right mouse button went down over a viewport and is still held

  // Viewports: slots beyond viewportCount keep their technique for when they come back.
  std::vector<ViewportSlot> slots;
  int viewportCount = 1;
  std::set<std::string> selectedViews;  // debug views drawn as thumbnails under each viewport

  // Tools and status.
  bool magnifierPinned = false;         // checkbox; holding M shows it too
  bool plotPinned = false;              // checkbox; holding V shows the visibility plot too
  bool showDpdsPlot = false;            // the live dp/ds window (explorer/plot_window.h)
  bool screenshotRequested = false;     // the whole window, UI included
  bool viewportShotsRequested = false;  // each viewport's image alone, no UI
  std::string screenshotDir;            // where screenshots and exports go (see exportDir)
  std::string statusLine;               // last screenshot written, etc.
  double statusLineTime = -1e9;         // glfwGetTime() when statusLine was set: shown on screen for a while
  // Lecture settings: UI size (fonts rebuilt at 16 px x uiScale), help window, linked parameters.
  float uiScale = 1.0f;
  bool showHelp = false;
  bool quitRequested = false;          // Ctrl+Q: the loop closes the window after this frame
  bool showColourKeys = true;          // each heat-map view's key over its image (K toggles)
  bool linkAllParams = false;          // every parameter edit goes to every viewport declaring it
  std::set<std::string> linkedParams;  // keys linked one by one (the chain button beside a widget)
  std::string settingsPath;            // "" = settings are neither read nor written (scripted runs)
  std::string settingsMessage;         // a settings problem (corrupt file set aside), shown in the panel
  std::string renderError;             // exception from the last frame, shown until a frame works again
  float smoothedFrameMs = 0.0f;
  int hoveredViewport = -1;  // viewport image under the mouse in the previous frame
  // That tile's rectangle (ImGui coordinates): at 2-3 fps the mouse can leave it between two
  // frames, and the wheel then meant for the side panel changed the camera speed (#26).
  float hoveredTileMin[2] = {0, 0}, hoveredTileMax[2] = {0, 0};
  // Accuracy panel and `error` view (owned by the frame loop; null outside it).
  ErrorPanel* errorPanel = nullptr;
};

// After a frame was rendered: counts it (a cut restarts the count at 1) and freezes when the
// count reaches freezeAtFrame.
void countRenderedFrame(ExplorerState& state, bool cut);
// Renders still frames until `frames` have been rendered since a cut, then freezes: continues
// the current run when it has not passed `frames` yet, else cuts and starts again.
void runStillFramesTo(ExplorerState& state, int frames);

// Viewports whose technique.layout was changed in place (the panel, a linked edit) get their
// technique rebuilt over that layout (recomposed: shared values kept, history reset). Returns
// how many were rebuilt.
int applyCompositionChanges(ExplorerState& state);

// Loads a scene (id or path) and hands it to the renderer; on failure the current scene stays
// and the message goes to state.sceneError. Returns true on success.
bool switchScene(ExplorerState& state, Renderer& renderer, const std::string& idOrPath);
// Camera cut to a named scene camera (stops path playback).
void jumpToCamera(ExplorerState& state, const Camera& camera);
void startCameraPath(ExplorerState& state, const CameraPath& path);
// The light's direction as angles of the direction towards the light: azimuth about +y from +z,
// elevation above the horizontal plane (degrees).
glm::vec2 lightAngles(const Light& light);
glm::vec3 directionFromLightAngles(float azimuthDeg, float elevationDeg);  // the travel direction
// Points the scene's light along `direction` (normalised; ignored if zero or not finite). Every
// accumulation forgets its history (a cut: it was gathered under the old light) and the accuracy
// panel drops its references (traced under the old light). Returns true when the light changed.
bool setLightDirection(ExplorerState& state, glm::vec3 direction);
// Moves a spot or point light to `position` (ignored if not finite, or for a directional light),
// a cut as above. Returns true when the light moved.
bool setLightPosition(ExplorerState& state, glm::vec3 position);
// A scene of several lights: makes Scene::otherLights[k] the light the debug views, the drag
// fields and the accuracy panel show (it trades places with Scene::light; it must be shadowed),
// a cut as above. Returns true when the shown light changed.
bool showLightInViews(ExplorerState& state, size_t k);
// Turns Scene::otherLights[k]'s shadow on or off (off: it lights through casters and costs no
// maps), a cut as above. Returns true when it changed.
bool setOtherLightShadow(ExplorerState& state, size_t k, bool shadow);
// Replaces a viewport's technique by a preset with its default overrides.
void setViewportPreset(ExplorerState& state, int slot, const std::string& presetId);
// Makes sure the first viewportCount slots exist; new ones get presets not shown yet, so
// going from 1 to 2 viewports immediately compares two different techniques.
void ensureViewportSlots(ExplorerState& state);
// Union of the debug views the shown viewports offer, in a stable order (common ones first),
// then the explorer's own `error` view (drawn from the accuracy panel, not by the renderer).
std::vector<std::string> availableViewNames(const ExplorerState& state);
// Copies the selection into each viewport's shownViews (only the views it has), and drops an
// enlarged view that is no longer selected.
void applySelectedViews(ExplorerState& state);
std::vector<Viewport*> shownViewports(const ExplorerState& state);
// Whether an edit of `key` goes to the other viewports (linkAllParams or linked one by one).
bool paramLinked(const ExplorerState& state, const std::string& key);
// After viewport `source` changed `key`: the same value in every other shown viewport whose
// technique declares the key (its range permitting; a value it rejects leaves it unchanged and
// records the message in that slot's error). Returns how many viewports were changed.
int propagateLinkedParam(ExplorerState& state, int source, const std::string& key);
// Tab through the big image of every shown viewport: colour, then each offered debug view in
// turn (a view chosen this way is also selected, so it is rendered). step = +1 or -1. Returns
// the view now shown ("" = colour).
std::string cycleEnlargedView(ExplorerState& state, int step);
float sceneDiagonal(const Scene& scene);

}  // namespace sl
