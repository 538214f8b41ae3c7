// `shadowlab figure` as a user meets it, and the explorer's tour player applying steps to the
// window's state (no window needed: the player drives the same state the panels do).
#include "explorer/explorer_state.h"
#include "explorer/shortcuts.h"
#include "explorer/tour_player.h"
#include "explorer/viewport_area.h"
#include "gl_test_util.h"
#include "sanitizer_report.h"

#include <stb_image.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace sl {
namespace {

struct TourRunResult {
  int code = -1;
  std::string output;
};

TourRunResult runTour(const std::string& args) {
  const std::string cmd = std::string(SHADOWLAB_BINARY) + " " + args + " 2>&1";
  TourRunResult r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), buf.size(), p)) r.output += buf.data();
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  test::expectNoSanitizerReport(r.output, args);
  return r;
}

std::string writeTour(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

const char* kTwoSteps = R"({"title": "t", "steps": [
  {"title": "one", "caption": "first", "scene": "basic",
   "viewports": [{"technique": "standard", "views": ["aliasing"]}, "pcf"]},
  {"title": "two", "caption": "second", "scene": "columns", "requires": ["planned-only"],
   "viewports": ["planned-only", "lispsm"], "plot": {"kind": "dpds", "techniques": ["uniform", "lispsm"]}}
]})";

TEST(FigureCli, StepWritesAPngOfAllPanels) {
  const std::string tour = writeTour("figure_two.json", kTwoSteps);
  const std::string png = ::testing::TempDir() + "figure_step1.png";
  std::filesystem::remove(png);
  const TourRunResult r = runTour("figure --tour " + tour + " --step 1 --size 96x64 --out " + png);
  ASSERT_EQ(r.code, 0) << r.output;
  int w = 0, h = 0, n = 0;
  ASSERT_TRUE(stbi_info(png.c_str(), &w, &h, &n)) << png;
  EXPECT_GE(w, 3 * 96);  // colour + aliasing of viewport 1, colour of viewport 2
  EXPECT_GE(h, 64);
  EXPECT_NE(r.output.find("3 panels"), std::string::npos) << r.output;
}

TEST(FigureCli, AllWritesEveryStepAndThePlot) {
  const std::string tour = writeTour("figure_all.json", kTwoSteps);
  const std::string dir = ::testing::TempDir() + "figure_all";
  std::filesystem::remove_all(dir);
  const TourRunResult r = runTour("figure --tour " + tour + " --all --size 80x48 --out " + dir);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/step-01.png"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/step-02.png"));
  EXPECT_NE(r.output.find("not built yet"), std::string::npos) << r.output;
  std::ifstream svg(dir + "/step-02.svg");
  ASSERT_TRUE(svg.good()) << "no plot written";
  const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("lispsm"), std::string::npos);
}

// --check prints each claim with both numbers and fails (5) when one does not hold: standard
// cannot have a thousandth of uniform's wrong pixels, and uniform is not better than standard.
TEST(FigureCli, CheckReportsClaimsAndFailsOnOneThatDoesNotHold) {
  const std::string tour = writeTour("figure_claims.json", R"({"title": "t", "steps": [
    {"title": "fit", "scene": "basic", "camera": {"position": [1.5, 3.2, 2.4], "target": [0.7, 0.2, 0.3]},
     "viewports": [{"technique": "uniform", "set": ["shadowmap.size=256"]},
                   {"technique": "standard", "set": ["shadowmap.size=256"]}],
     "claims": [{"better": 2, "than": 1}, {"better": 2, "than": 1, "factor": 1000}]}]})");
  const TourRunResult r = runTour("figure --tour " + tour + " --step 1 --size 160x90 --check --out " +
                                  ::testing::TempDir() + "figure_claims.png");
  EXPECT_EQ(r.code, 5) << r.output;
  EXPECT_NE(r.output.find("viewport 2 (standard)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("claimed 1x fewer, holds"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("claimed 1000x fewer, does NOT hold"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("1 claim(s) do not hold"), std::string::npos) << r.output;
}

TEST(FigureCli, BadInputIsAClearError) {
  const std::string tour = writeTour("figure_bad.json", kTwoSteps);
  TourRunResult r = runTour("figure --tour " + tour + " --step 3 --out /tmp/never.png");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("has steps 1 to 2"), std::string::npos) << r.output;
  const std::string broken = writeTour("figure_broken.json", R"({"steps": [{"title": "x", "viewports": ["nope"]}]})");
  r = runTour("figure --tour " + broken + " --step 1 --out /tmp/never.png");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("figure_broken.json: steps[0] (\"x\").viewports[0].technique"), std::string::npos)
      << r.output;
  r = runTour("figure --tour " + tour + " --out /tmp/never.png");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("--step N or --all"), std::string::npos) << r.output;
  for (const char* bad : {"16:0", "wide", "0", "100:1", "4:3:2"}) {
    r = runTour("figure --tour " + tour + " --step 1 --aspect " + bad + " --out /tmp/never.png");
    EXPECT_EQ(r.code, 1) << bad;
    EXPECT_NE(r.output.find(std::string("--aspect ") + bad + ": expected W:H"), std::string::npos) << r.output;
  }
}

// An explorer state on the basic scene, handed to the harness's renderer (the player's tests).
ExplorerState basicSceneState(test::GlHarness& h) {
  ExplorerState state;
  state.assetsDir = defaultAssetsDir();
  state.scene = std::make_unique<Scene>(loadScene("basic", state.assetsDir));
  h.renderer.setScene(*state.scene);
  return state;
}

TEST(TourPlayer, StepsSetSceneViewportsViewsAndLight) {
  test::GlHarness h;
  ExplorerState state = basicSceneState(h);
  const std::string tour = writeTour("player.json", R"({"steps": [
    {"title": "a", "scene": "columns", "viewports": [{"technique": "pcf", "set": ["pcf.kernel=5"], "views": ["texels"]},
                                                   "lispsm", "psm"]},
    {"title": "b", "scene": "basic", "light": [90, 45], "camera": "top", "viewports": ["pixel-correct"]}]})");
  TourPlayer player;
  ImGui::CreateContext();                // the player sets the font scale for presenter mode
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the source tree
  ASSERT_TRUE(player.start(state, h.renderer, tour, 1, false));
  EXPECT_EQ(state.scene->name, "columns");
  EXPECT_EQ(state.viewportCount, 3);  // exactly the step's three, no fourth from before
  EXPECT_EQ(state.slots[0].viewport->technique.presetId, "pcf");
  EXPECT_EQ(state.slots[0].viewport->technique.params.i("pcf.kernel"), 5);
  EXPECT_EQ(state.slots[2].viewport->technique.presetId, "psm");
  EXPECT_EQ(state.selectedViews, std::set<std::string>{"texels"});
  player.show(state, h.renderer, 1);
  EXPECT_EQ(player.step(), 1u);
  EXPECT_EQ(state.scene->name, "basic");
  EXPECT_EQ(state.viewportCount, 1);
  EXPECT_EQ(state.cameraName, "top");
  EXPECT_TRUE(state.selectedViews.empty());
  const glm::vec3 expected = directionFromLightAngles(90, 45);
  EXPECT_LT(glm::length(state.scene->light.direction - expected), 1e-4f);
  player.show(state, h.renderer, 5);  // past the end: stays on the last step
  EXPECT_EQ(player.step(), 1u);
  ImGui::DestroyContext();
}

// The keys a presenter uses, recorded as GLFW's key callback records them (explorer/shortcuts.h).
TEST(TourPlayer, KeysStepAndTogglePresenterMode) {
  test::GlHarness h;
  ExplorerState state = basicSceneState(h);
  const std::string tour = writeTour("keys.json", R"({"steps": [{"title": "a", "viewports": ["standard"]},
    {"title": "b", "viewports": ["pcf"]}, {"title": "c", "viewports": ["vsm"]}]})");
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the source tree
  io.DisplaySize = ImVec2(320, 240);
  io.DeltaTime = 1.0f / 60.0f;
  unsigned char* pixels = nullptr;
  int w = 0, hgt = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &hgt);
  TourPlayer player;
  ASSERT_TRUE(player.start(state, h.renderer, tour, 1, false));
  // One press recorded before a frame, as a tap between two polls.
  auto press = [&](int key) {
    clearKeyPresses();
    recordKeyPress(key, 0);
    ImGui::NewFrame();
    player.handleKeys(state, h.renderer);
    ImGui::EndFrame();
    clearKeyPresses();
  };
  press(267);  // GLFW_KEY_PAGE_DOWN
  EXPECT_EQ(player.step(), 1u);
  EXPECT_EQ(state.slots[0].viewport->technique.presetId, "pcf");
  press(262);  // GLFW_KEY_RIGHT
  EXPECT_EQ(player.step(), 2u);
  press(262);  // already on the last step
  EXPECT_EQ(player.step(), 2u);
  press(266);  // GLFW_KEY_PAGE_UP
  EXPECT_EQ(player.step(), 1u);
  EXPECT_FALSE(player.presenter());
  press(294);  // GLFW_KEY_F5
  EXPECT_TRUE(player.presenter());
  EXPECT_GT(io.FontGlobalScale, 1.5f);
  press(294);
  EXPECT_FALSE(player.presenter());
  ImGui::DestroyContext();
}

// Issue #23: the step's plot window opened over viewport 2 (on the LogPSM step, the very map the
// caption is about). A plot step now takes a strip on the right that the viewports are laid out
// beside; a step without a plot takes none.
TEST(TourPlayer, AStepsPlotHasAStripBesideTheViewports) {
  test::GlHarness h;
  ExplorerState state = basicSceneState(h);
  const std::string tour = writeTour("plotstrip.json", R"({"steps": [{"title": "a", "viewports": ["standard"]},
    {"title": "b", "scene": "columns", "viewports": ["lispsm", "logpsm", "psm"],
     "plot": {"kind": "dpds", "techniques": ["lispsm", "logpsm"]}}]})");
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.DisplaySize = ImVec2(1280, 720);
  unsigned char* pixels = nullptr;
  int w = 0, hgt = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &hgt);
  TourPlayer player;
  const ImVec2 area(1280, 720);
  ASSERT_TRUE(player.start(state, h.renderer, tour, 1, false));
  ImGui::NewFrame();
  EXPECT_EQ(player.plotStripWidth(area), 0.0f);
  ImGui::EndFrame();
  ASSERT_TRUE(player.start(state, h.renderer, tour, 2, false));
  ImGui::NewFrame();
  const float strip = player.plotStripWidth(area);
  EXPECT_GT(strip, 200.0f);
  EXPECT_LE(strip, 0.45f * area.x);
  const MainAreaLayout layout = layoutMainArea(ImVec2(0, 0), ImVec2(area.x - strip, area.y), 3, 3, ImVec2(1, 1));
  for (const ViewportTile& t : layout.tiles) {
    EXPECT_LE(t.imageMin.x + t.imageSize.x, area.x - strip);
    EXPECT_LE(t.headerMin.x + t.headerSize.x, area.x - strip);
  }
  ImGui::EndFrame();
  ImGui::DestroyContext();
}

// A step with still-frame counts plays like a slide with builds: it freezes at each count in
// turn before "next" leaves it, and "previous" re-renders an earlier count from a cut.
TEST(TourPlayer, StepFramesFreezeAtEachCountBeforeTheNextStep) {
  test::GlHarness h;
  ExplorerState state = basicSceneState(h);
  const std::string tour = writeTour("frames.json", R"({"steps": [{"title": "a", "viewports": ["standard"]},
    {"title": "b", "viewports": ["pixel-correct"], "frames": [1, 5, 9]}, {"title": "c", "viewports": ["vsm"]}]})");
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  TourPlayer player;
  ASSERT_TRUE(player.start(state, h.renderer, tour, 1, false));
  EXPECT_EQ(state.freezeAtFrame, 0);  // a step of one frame runs live
  // What the frame loop does: render until frozen, counting frames since the cut.
  auto runUntilFrozen = [&] {
    for (int i = 0; i < 50 && !state.frozen; ++i) {
      countRenderedFrame(state, state.cutPending);
      state.cutPending = false;
    }
  };
  player.next(state, h.renderer);
  ASSERT_EQ(player.step(), 1u);
  EXPECT_EQ(player.stageFrames(), 1);
  runUntilFrozen();
  EXPECT_TRUE(state.frozen);
  EXPECT_EQ(state.framesSinceCut, 1);
  player.next(state, h.renderer);  // same step, on to 5 frames without a cut
  EXPECT_EQ(player.step(), 1u);
  EXPECT_FALSE(state.frozen);
  EXPECT_FALSE(state.cutPending);
  runUntilFrozen();
  EXPECT_EQ(state.framesSinceCut, 5);
  player.next(state, h.renderer);
  runUntilFrozen();
  EXPECT_EQ(state.framesSinceCut, 9);
  EXPECT_EQ(player.stageFrames(), 9);
  player.previous(state, h.renderer);  // back to 5 frames: from a cut
  EXPECT_TRUE(state.cutPending);
  runUntilFrozen();
  EXPECT_EQ(state.framesSinceCut, 5);
  player.next(state, h.renderer);
  runUntilFrozen();
  player.next(state, h.renderer);  // past the last count: the next step, which runs live
  EXPECT_EQ(player.step(), 2u);
  EXPECT_FALSE(state.frozen);
  EXPECT_EQ(state.freezeAtFrame, 0);
  player.previous(state, h.renderer);  // back onto the staged step: its first count again
  EXPECT_EQ(player.step(), 1u);
  EXPECT_EQ(player.stageFrames(), 1);
  ImGui::DestroyContext();
}

}  // namespace
}  // namespace sl
