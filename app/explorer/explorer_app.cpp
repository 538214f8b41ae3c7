// The explorer's frame loop. The window and ImGui set-up are explorer_window.cpp; panels, the
// viewport area, the camera and the magnifier live in their own files; this one wires them to
// GLFW, ImGui and the renderer.
#include "explorer/explorer.h"

#include "explorer/error_panel.h"
#include "explorer/explorer_state.h"
#include "explorer/explorer_window.h"
#include "explorer/magnifier.h"
#include "explorer/plot_window.h"
#include "explorer/visibility_plot.h"
#include "explorer/screenshot.h"
#include "explorer/session_files.h"
#include "explorer/settings.h"
#include "explorer/shortcuts.h"
#include "explorer/soak.h"
#include "explorer/side_panel.h"
#include "explorer/presenter_window.h"
#include "explorer/tour_player.h"
#include "explorer/ui_scale.h"
#include "explorer/viewport_area.h"
#include "gl/gl_util.h"
#include "gl/shader_library.h"
#include "render/renderer.h"
#include "technique.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <vector>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

namespace sl {

namespace {

constexpr double kShaderPollSeconds = 0.25;  // hot reload shows an edit within half a second
constexpr float kMaxFrameSeconds = 0.1f;     // a stall (breakpoint, resize) must not fling the camera

const char* const kNoDisplayMessage =
    "shadowlab: no display found (DISPLAY unset or X server unreachable); run headless:\n"
    "  shadowlab render --scene basic --technique standard --out out.png\n";

bool keyDown(GLFWwindow* window, int key) { return glfwGetKey(window, key) == GLFW_PRESS; }

// Fly controls apply while the mouse is over a viewport image (or a look drag that started
// there is still held), never while a text field has the keyboard.
FlyInput readFlyInput(GLFWwindow* window, ExplorerState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  // Last frame's hover, and the mouse still inside that tile now.
  const bool overViewport = state.hoveredViewport >= 0 && io.MousePos.x >= state.hoveredTileMin[0] &&
                            io.MousePos.y >= state.hoveredTileMin[1] && io.MousePos.x < state.hoveredTileMax[0] &&
                            io.MousePos.y < state.hoveredTileMax[1];
  if (overViewport && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) state.looking = true;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Right)) state.looking = false;

  FlyInput input;
  if ((overViewport || state.looking) && !io.WantTextInput) {
    auto axis = [window](int negative, int positive) {
      return float(keyDown(window, positive)) - float(keyDown(window, negative));
    };
    input.move = glm::vec3(axis(GLFW_KEY_A, GLFW_KEY_D), axis(GLFW_KEY_Q, GLFW_KEY_E), axis(GLFW_KEY_S, GLFW_KEY_W));
    input.fast = keyDown(window, GLFW_KEY_LEFT_SHIFT) || keyDown(window, GLFW_KEY_RIGHT_SHIFT);
  }
  if (state.looking) input.lookPixels = glm::vec2(io.MouseDelta.x, io.MouseDelta.y);
  if (overViewport) input.scrollSteps = io.MouseWheel;
  return input;
}

void advanceCameraAndTime(GLFWwindow* window, ExplorerState& state, float dt) {
  const FlyInput input = readFlyInput(window, state);
  // Touching the controls during path playback hands the camera back to the user.
  if (state.playingPath && (input.move != glm::vec3(0.0f) || input.lookPixels != glm::vec2(0.0f)))
    state.playingPath = nullptr;
  if (state.playingPath) {
    if (!state.paused) state.pathTime += dt;
    const CameraPath& path = *state.playingPath;
    state.camera.setPose(path.sample(float(state.pathTime), state.scene->cameras.front()));
    if (state.pathTime >= path.duration()) state.playingPath = nullptr;
  } else {
    state.camera.update(input, dt);
  }
  if (!state.paused) state.sceneTime += dt;
}

// The renderer leaves its own framebuffer, masks and tests bound; the ImGui backend restores
// only what it changes itself, so give it the default framebuffer in a neutral state.
void prepareDefaultFramebuffer(int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glClearColor(0.07f, 0.07f, 0.08f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

// Returns false when the frame failed (the panel shows why).
bool renderViewports(Renderer& renderer, ExplorerState& state, const MainAreaLayout& layout) {
  if (state.frozen && !state.stepRequested) return false;
  state.stepRequested = false;
  FrameInput in;
  in.camera = state.camera.camera();
  in.time = state.sceneTime;
  in.width = layout.renderWidth;
  in.height = layout.renderHeight;
  in.cut = state.cutPending;
  try {
    renderer.render(in, shownViewports(state));
    state.cutPending = false;
    countRenderedFrame(state, in.cut);
    state.renderError.clear();
    return true;
  } catch (const std::exception& e) {
    // Keep the window alive: the panel shows the message and the next frame tries again.
    if (state.renderError != e.what()) std::cerr << "shadowlab: render failed: " << e.what() << "\n";
    state.renderError = e.what();
  }
  return false;
}

// Fills the viewport slots with the start techniques and selects the debug views asked for.
// False (after saying why) when --view names a view none of them offers.
bool placeStartViewports(ExplorerState& state, std::vector<Technique>& techniques) {
  state.slots.resize(kMaxViewports);
  for (size_t i = 0; i < techniques.size() && i < state.slots.size(); ++i)
    state.slots[i].viewport = std::make_unique<Viewport>(std::move(techniques[i]));
  state.viewportCount = viewportCountFor(techniques.size());
  ensureViewportSlots(state);
  const std::vector<std::string> offered = availableViewNames(state);
  for (const std::string& view : state.options.debugViews) {
    const bool known = std::find(offered.begin(), offered.end(), view) != offered.end();
    if (!known && (state.options.fromSettings || state.options.firstStartDefaults)) continue;  // not offered now
    if (!known) {
      std::cerr << "shadowlab: no debug view '" << view << "'; these techniques offer:";
      for (const std::string& name : offered) std::cerr << " " << name;
      std::cerr << "\n";
      return false;
    }
    state.selectedViews.insert(view);
  }
  for (size_t i = 0; i < state.options.enlargedViews.size() && i < state.slots.size(); ++i) {
    const std::string& view = state.options.enlargedViews[i];
    if (view.empty() || std::find(offered.begin(), offered.end(), view) == offered.end()) continue;
    state.selectedViews.insert(view);
    state.slots[i].enlargedView = view;
  }
  state.magnifierPinned = state.options.magnifier;
  state.plotPinned = state.options.visibilityPlot;
  state.showDpdsPlot = state.options.dpdsPlot;
  state.cutPending = true;
  return true;
}

// What the keys and panels left behind, for scripts and the window tests
// (tests/explorer_smoke_test.cpp).
void printFrameReport(GLFWwindow* window, const ExplorerState& state, const TourPlayer& tour,
                      std::vector<double> frameSeconds) {
  std::sort(frameSeconds.begin(), frameSeconds.end());
  int w = 0, h = 0;
  glfwGetWindowSize(window, &w, &h);
  std::printf("explorer: %zu frames timed, median frame %.1f ms (%.1f fps), window %dx%d, %s\n", frameSeconds.size(),
              frameSeconds[frameSeconds.size() / 2] * 1000.0, 1.0 / frameSeconds[frameSeconds.size() / 2], w, h,
              glRendererName().c_str());
  std::printf(
      "explorer: state viewports=%d ui_scale=%.3f paused=%d frozen=%d frames_since_cut=%d colour_keys=%d "
      "help=%d dpds_plot=%d enlarged=%s tour_step=%zu tour_frames=%d\n",
      state.viewportCount, state.uiScale, int(state.paused), int(state.frozen), state.framesSinceCut,
      int(state.showColourKeys), int(state.showHelp), int(state.showDpdsPlot),
      state.slots.empty() || state.slots[0].enlargedView.empty() ? "-" : state.slots[0].enlargedView.c_str(),
      tour.active() ? tour.step() + 1 : 0, tour.active() ? tour.stageFrames() : 0);
}

// The frame loop, with what it carries from one frame to the next.
struct FrameLoop {
  GLFWwindow* window;
  ExplorerState& state;
  ShaderLibrary& shaders;
  Renderer& renderer;
  ErrorPanel& errorPanel;
  TourPlayer& tour;
  SoakDriver* soak;
  const int maxFrames;
  double lastTime = glfwGetTime(), lastShaderPoll = lastTime;
  std::vector<double> frameSeconds;  // whole frames (render + UI + swap), for --frames reports
  std::vector<std::string> printedShaderErrors;
  float appliedUiScale = state.uiScale;
  PresenterWindow presenterWindow;

  // Until the window closes, --frames runs out or the soak ends. False when the exit screenshot
  // could not be written.
  bool run();
  float advanceClock(int frame, double now);
  void reloadShaders(double now);
  void beginUi(double now);
  bool drawFrame(double now, float dt, int fbWidth, int fbHeight, bool lastFrame);
  MainAreaResult drawOverlays(const MainAreaLayout& layout, float panelWidth, bool plotKey);
  bool saveFrameOutputs(double now, int fbWidth, int fbHeight, bool lastFrame);
};

bool FrameLoop::run() {
  for (int frame = 0;; ++frame) {
    clearKeyPresses();
    presenterWindow.follow(window, tour.presenter(), state.options.monitor);
    glfwPollEvents();
    // A close request still draws one more frame, so --screenshot-on-exit has something to read.
    const bool lastFrame =
        glfwWindowShouldClose(window) || (maxFrames > 0 && frame + 1 >= maxFrames) || (soak && soak->done());
    int fbWidth = 0, fbHeight = 0;
    glfwGetFramebufferSize(window, &fbWidth, &fbHeight);
    if ((fbWidth == 0 || fbHeight == 0) && !lastFrame) {  // minimized
      glfwWaitEventsTimeout(0.1);
      continue;
    }
    const double now = glfwGetTime();
    const float dt = advanceClock(frame, now);
    if (!drawFrame(now, dt, fbWidth, fbHeight, lastFrame)) return false;
    glfwSwapBuffers(window);
    if (soak) soak->afterFrame(state);
    if (lastFrame) return true;
  }
}

// Returns the camera's time step for this frame.
float FrameLoop::advanceClock(int frame, double now) {
  const double frameTime = now - lastTime;
  lastTime = now;
  const float dt = std::min(float(frameTime), kMaxFrameSeconds);
  if (frame > 5) frameSeconds.push_back(frameTime);  // skip start-up and shader builds
  // The display shows the real frame time; only camera motion uses the clamped step.
  state.smoothedFrameMs += (float(frameTime) * 1000.0f - state.smoothedFrameMs) * 0.1f;
  if (now - lastShaderPoll >= kShaderPollSeconds) reloadShaders(now);
  return dt;
}

void FrameLoop::reloadShaders(double now) {
  shaders.reloadChanged();
  lastShaderPoll = now;
  // The panel shows them; a terminal gets each new one once too (file:line first).
  std::vector<std::string> errors = shaders.errors();
  for (const std::string& e : errors)
    if (std::find(printedShaderErrors.begin(), printedShaderErrors.end(), e) == printedShaderErrors.end())
      std::cerr << "shadowlab: shader error (the last good program keeps running): " << e << "\n";
  printedShaderErrors = std::move(errors);
}

// Starts the ImGui frame and runs what may change the viewports before they render.
void FrameLoop::beginUi(double now) {
  if (state.uiScale != appliedUiScale) {  // fonts are rebuilt between frames, never inside one
    applyUiScale(state.uiScale);
    appliedUiScale = state.uiScale;
  }
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  releaseKeysSeenDown();
  handleShortcuts(state);
  if (state.quitRequested) glfwSetWindowShouldClose(window, GLFW_TRUE);  // seen at the next frame's start
  tour.handleKeys(state, renderer);
  if (soak) soak->beforeFrame(state, renderer, shaders, now);
  if (!tour.presenter()) drawSidePanel(state, renderer, shaders);
  applyCompositionChanges(state);
  ensureViewportSlots(state);
  applySelectedViews(state);
}

// False when the exit screenshot could not be written.
bool FrameLoop::drawFrame(double now, float dt, int fbWidth, int fbHeight, bool lastFrame) {
  beginUi(now);
  const ImGuiIO& io = ImGui::GetIO();
  const float panelWidth =
      tour.presenter() ? 0.0f : std::min(sidePanelWidth(state.uiScale, io.DisplaySize.x), io.DisplaySize.x - 1.0f);
  const int thumbnails = availableViewNames(state).empty() ? 0 : static_cast<int>(state.selectedViews.size());
  // A step's plot has a strip of its own on the right: it hides no viewport (#23).
  const ImVec2 tourArea(io.DisplaySize.x - panelWidth, io.DisplaySize.y);
  const MainAreaLayout layout =
      layoutMainArea(ImVec2(panelWidth, 0),
                     ImVec2(tourArea.x - tour.plotStripWidth(tourArea), tourArea.y - tour.captionHeight(tourArea)),
                     state.viewportCount, thumbnails, io.DisplayFramebufferScale);
  advanceCameraAndTime(window, state, dt);
  // The visibility plot (hold V) reads the G-buffer under the mouse.
  const bool plotKey = state.plotPinned || (keyDown(window, GLFW_KEY_V) && !io.WantTextInput);
  renderer.keepGBuffer = errorPanel.wantsGBuffer() || plotKey;
  const bool rendered = renderViewports(renderer, state, layout);
  errorPanel.afterRender(state, renderer, layout.renderWidth, layout.renderHeight, rendered);

  const MainAreaResult area = drawOverlays(layout, panelWidth, plotKey);
  ImGui::Render();
  prepareDefaultFramebuffer(fbWidth, fbHeight);
  blitToScreen(area.blits, fbHeight, io.DisplayFramebufferScale);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  return saveFrameOutputs(now, fbWidth, fbHeight, lastFrame);
}

// Drawn after rendering so the images reference this frame's textures (a resize may have
// replaced them).
MainAreaResult FrameLoop::drawOverlays(const MainAreaLayout& layout, float panelWidth, bool plotKey) {
  const ImGuiIO& io = ImGui::GetIO();
  const MainAreaResult area = drawMainArea(layout, state);
  state.hoveredViewport = area.hoveredViewport;
  state.hoveredTileMin[0] = area.hoveredTileMin.x, state.hoveredTileMin[1] = area.hoveredTileMin.y;
  state.hoveredTileMax[0] = area.hoveredTileMax.x, state.hoveredTileMax[1] = area.hoveredTileMax.y;
  tour.drawCaption(state, renderer, ImVec2(panelWidth, 0), ImVec2(io.DisplaySize.x - panelWidth, io.DisplaySize.y));
  const ImVec2 tourArea(io.DisplaySize.x - panelWidth, io.DisplaySize.y);
  const float plotWidth = tour.plotStripWidth(tourArea);
  tour.drawPlot(ImVec2(io.DisplaySize.x - plotWidth, 0), ImVec2(plotWidth, tourArea.y - tour.captionHeight(tourArea)));
  drawDpdsWindow(state, layout.renderWidth, layout.renderHeight, ImVec2(panelWidth, 0),
                 ImVec2(io.DisplaySize.x - panelWidth, io.DisplaySize.y));
  const bool magnifierKey = keyDown(window, GLFW_KEY_M) && !io.WantTextInput;
  if ((state.magnifierPinned || magnifierKey) && area.hoveredImage.valid())
    drawMagnifier(area.hoveredImage, io.MousePos);
  if (plotKey && area.hoveredViewport >= 0 && area.hoveredViewport < state.viewportCount)
    drawVisibilityPlot(shaders, renderer, shownViewports(state), size_t(area.hoveredViewport), area.hoveredImage,
                       io.MousePos);

  drawHelpWindow(state);
  return area;
}

// Screenshots, accuracy exports and settings; false when the exit screenshot failed.
bool FrameLoop::saveFrameOutputs(double now, int fbWidth, int fbHeight, bool lastFrame) {
  if (lastFrame && state.options.saveOnExit) {
    state.screenshotRequested = state.viewportShotsRequested = true;
    exportAccuracy(state);
  }
  saveRequestedScreenshots(state, fbWidth, fbHeight);
  saveSettingsIfChanged(state, now, lastFrame);
  if (lastFrame && !state.options.screenshotOnExit.empty()) {
    const std::string error = writeWindowPng(fbWidth, fbHeight, state.options.screenshotOnExit);
    if (!error.empty()) {
      std::cerr << "shadowlab: " << error << "\n";
      return false;
    }
  }
  return true;
}

// Owns everything holding GL objects, so it all goes before the context does.
int runFrames(GLFWwindow* window, ExplorerState& state, std::vector<Technique> techniques) {
  ShaderLibrary shaders(state.shaderDir);
  Renderer renderer(shaders);
  renderer.waitForPassTimes = false;  // on a GPU: the newest pass times that have arrived, no stall
  renderer.setScene(*state.scene);
  // After the renderer, so it goes first: it joins its worker and frees its textures while the
  // context and the scene still exist.
  ErrorPanel errorPanel;
  struct PanelLink {
    ExplorerState& state;
    ~PanelLink() { state.errorPanel = nullptr; }
  } panelLink{state};
  state.errorPanel = &errorPanel;
  if (!placeStartViewports(state, techniques)) return 1;
  TourPlayer tour;
  if (!state.options.tour.empty() &&
      !tour.start(state, renderer, state.options.tour, state.options.tourStep, state.options.presenter))
    return 1;

  const int maxFrames = state.options.maxFrames;
  std::unique_ptr<SoakDriver> soak;
  if (state.options.soakSeconds > 0) soak = std::make_unique<SoakDriver>(state.options.soakSeconds, state.shaderDir);
  glfwSwapInterval(maxFrames > 0 || soak ? 0 : 1);  // smoke runs should not wait for vsync
  FrameLoop loop{window, state, shaders, renderer, errorPanel, tour, soak.get(), maxFrames};
  if (!loop.run()) return 1;
  if (maxFrames > 0 && !loop.frameSeconds.empty()) printFrameReport(window, state, tour, loop.frameSeconds);
  if (soak) return soak->finish();
  // In --frames mode a failing renderer must not look like success to scripts and tests.
  if (maxFrames > 0 && !state.renderError.empty()) return 1;
  return 0;
}

// Everything that can be checked without a window, so a typo fails fast with a clear message.
bool prepareState(const ExplorerOptions& options, ExplorerState& state, std::vector<Technique>& techniques) {
  state.options = options;
  state.shaderDir = options.shaderDir.empty() ? defaultShaderDir() : options.shaderDir;
  state.assetsDir = options.assetsDir.empty() ? defaultAssetsDir() : options.assetsDir;
  try {
    state.sceneIds = builtinSceneIds(state.assetsDir);
    try {
      state.scene = std::make_unique<Scene>(loadScene(options.scene, state.assetsDir));
      state.sceneLabel = options.scene;
    } catch (const std::exception& e) {
      if (!options.fromSettings) throw;
      // A saved scene that moved or broke must not keep the explorer from starting.
      state.settingsMessage = std::string("saved scene not loaded (") + e.what() + "); showing basic";
      std::cerr << "shadowlab: " << state.settingsMessage << "\n";
      state.scene = std::make_unique<Scene>(loadScene("basic", state.assetsDir));
      state.sceneLabel = "basic";
    }
    techniques.push_back(makeTechnique(options.technique, options.overrides));
    for (size_t i = 0; i < options.compareTechniques.size() && techniques.size() < size_t(kMaxViewports); ++i)
      techniques.push_back(makeTechnique(options.compareTechniques[i], i < options.compareOverrides.size()
                                                                           ? options.compareOverrides[i]
                                                                           : std::vector<std::string>{}));
  } catch (const std::exception& e) {
    std::cerr << "shadowlab: " << e.what() << "\n";
    return false;
  }
  const Camera* start = &state.scene->cameras.front();
  if (!options.camera.empty()) {
    start = state.scene->findCamera(options.camera);
    if (!start) {
      std::cerr << "shadowlab: scene '" << state.scene->name << "' has no camera '" << options.camera << "'; it has:";
      for (const Camera& c : state.scene->cameras) std::cerr << " " << c.name;
      std::cerr << "\n";
      return false;
    }
  }
  jumpToCamera(state, *start);
  if (options.setLight)
    setLightDirection(state, directionFromLightAngles(options.lightAngles.x, options.lightAngles.y));
  return true;
}

}  // namespace

int runExplorer(const ExplorerOptions& options) {
  if (!displayConfigured()) {
    std::cerr << kNoDisplayMessage;
    return 2;
  }
  ExplorerState state;
  std::vector<Technique> techniques;  // one per viewport shown at start
  ExplorerOptions start = options;
  SettingsLoad saved = loadSettings(options.settingsPath);
  std::string problems = saved.problem;
  startLayout(start, saved.settings ? &*saved.settings : nullptr, problems);
  if (!problems.empty()) std::cerr << "shadowlab: " << problems << "\n";
  if (!prepareState(start, state, techniques)) return 1;
  state.settingsPath = options.settingsPath;
  if (!problems.empty()) state.settingsMessage = problems;
  if (saved.settings) applyStateSettings(state, *saved.settings);
  if (options.uiScale > 0.0f) state.uiScale = options.uiScale;
  state.showHelp = options.showHelp;
  if (!options.screenshotDir.empty()) state.screenshotDir = options.screenshotDir;

  installGlfwErrorRecorder();
  if (!glfwInit()) {
    std::cerr << kNoDisplayMessage << "  (GLFW: " << lastGlfwError() << ")\n";
    return 2;
  }
  if (const std::string bad = checkMonitorIndex(options.monitor); !bad.empty()) {
    std::cerr << "explorer: " << bad << "\n";
    glfwTerminate();
    return 1;
  }
  GLFWwindow* window = createExplorerWindow(options);
  if (!window) {
    std::cerr << kNoDisplayMessage << "  (GLFW could not open an OpenGL 4.5 core window: " << lastGlfwError() << ")\n";
    glfwTerminate();
    return 2;
  }
  glfwMakeContextCurrent(window);
  glfwSetWindowTitle(window, ("shadowlab explorer - " + state.sceneLabel).c_str());
  enableGlDebugOutput(false);
  keepGlDriverLoaded();
  setUpExplorerImGui(window, state.uiScale);

  int exitCode = 0;
  try {
    exitCode = runFrames(window, state, std::move(techniques));
  } catch (const std::exception& e) {
    std::cerr << "shadowlab: " << e.what() << "\n";
    exitCode = 1;
  }
  state.slots.clear();  // viewports own GL textures: free them while the context still exists
  shutDownExplorerImGui();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exitCode;
}

}  // namespace sl
