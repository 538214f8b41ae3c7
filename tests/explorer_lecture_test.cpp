// The lecture-ready explorer without a window: linked parameters, view cycling, settings
// (load, save, corrupt), colour keys, export folders and formats, shortcuts, camera speed.
#include "explorer/error_panel.h"
#include "explorer/explorer_state.h"
#include "explorer/screenshot.h"
#include "explorer/session_files.h"
#include "explorer/settings.h"
#include "explorer/shortcuts.h"
#include "tour/tour.h"
#include "explorer/ui_scale.h"
#include "explorer/tour_player.h"
#include "part/common_view_keys.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace sl {
namespace {

namespace fs = std::filesystem;

// A state with the given presets in the first viewports (no window, no GL: parts create their
// GL objects only when rendered).
ExplorerState stateWith(const std::vector<std::string>& presets) {
  ExplorerState state;
  state.slots.resize(kMaxViewports);
  for (size_t i = 0; i < presets.size(); ++i) setViewportPreset(state, int(i), presets[i]);
  state.viewportCount = viewportCountFor(presets.size());
  return state;
}

ParamSet& paramsOf(ExplorerState& state, int slot) { return state.slots[size_t(slot)].viewport->technique.params; }

struct LectureTempDir {
  fs::path path;
  LectureTempDir() {
    path = fs::temp_directory_path() / ("shadowlab-lecture-test-" + std::to_string(getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~LectureTempDir() { fs::remove_all(path); }
};

TEST(ExplorerLink, ALinkedParameterGoesToEveryViewportThatDeclaresIt) {
  ExplorerState state = stateWith({"standard", "pcf", "vsm"});
  ASSERT_EQ(state.viewportCount, 3);
  state.viewportCount = 4;
  ensureViewportSlots(state);  // the fourth slot gets a technique too
  EXPECT_FALSE(paramLinked(state, "shadowmap.size"));
  state.linkedParams.insert("shadowmap.size");
  EXPECT_TRUE(paramLinked(state, "shadowmap.size"));

  paramsOf(state, 1).set("shadowmap.size", 512);
  const int changed = propagateLinkedParam(state, 1, "shadowmap.size");
  EXPECT_EQ(changed, 3);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(paramsOf(state, i).get("shadowmap.size"), 512) << i;
  // Propagating again changes nothing.
  EXPECT_EQ(propagateLinkedParam(state, 1, "shadowmap.size"), 0);

  // A key that only one technique declares stays where it is.
  ASSERT_TRUE(paramsOf(state, 1).has("pcf.kernel")) << "pcf's own parameter was renamed";
  EXPECT_FALSE(paramsOf(state, 0).has("pcf.kernel"));
  EXPECT_EQ(propagateLinkedParam(state, 1, "pcf.kernel"), 0);

  // "link all" links every key; hidden viewports (beyond viewportCount) are left alone.
  state.linkAllParams = true;
  EXPECT_TRUE(paramLinked(state, "bias.constant"));
  state.viewportCount = 2;
  paramsOf(state, 0).set("shadowmap.size", 1024);
  EXPECT_EQ(propagateLinkedParam(state, 0, "shadowmap.size"), 1);
  EXPECT_EQ(paramsOf(state, 1).get("shadowmap.size"), 1024);
  EXPECT_EQ(paramsOf(state, 2).get("shadowmap.size"), 512);
  // A bad source slot is no crash.
  EXPECT_EQ(propagateLinkedParam(state, 7, "shadowmap.size"), 0);
}

TEST(ExplorerViews, TabCyclesEveryViewportThroughColourAndTheOfferedViews) {
  ExplorerState state = stateWith({"standard", "pixel-correct"});
  const std::vector<std::string> offered = availableViewNames(state);
  ASSERT_GT(offered.size(), 3u);
  EXPECT_EQ(cycleEnlargedView(state, 1), offered[0]);
  EXPECT_EQ(state.slots[0].enlargedView, offered[0]);
  EXPECT_TRUE(state.selectedViews.count(offered[0]));  // selected, so it is rendered
  EXPECT_EQ(cycleEnlargedView(state, -1), "");         // back to colour
  EXPECT_EQ(cycleEnlargedView(state, -1), offered.back());
  // A view that only pixel-correct offers: the standard viewport shows its colour image.
  for (size_t n = 0; n < offered.size() + 1; ++n) {
    const std::string v = cycleEnlargedView(state, 1);
    if (v == "confidence") {
      EXPECT_EQ(state.slots[0].enlargedView, "");
      EXPECT_EQ(state.slots[1].enlargedView, "confidence");
      return;
    }
  }
  FAIL() << "Tab never reached pixel-correct's confidence view";
}

ExplorerSettings sampleSettings() {
  ExplorerSettings s;
  s.scene = "columns";
  s.viewports = {{"pcf", {{"shadowmap.size", 512}, {"bias.constant", 1.25e-5}}, "aliasing"}, {"vsm", {}, ""}};
  s.views = {"aliasing", "texels"};
  s.uiScale = 1.5f;
  s.cameraSpeed = 0.02f;
  s.screenshotDir = "/tmp/somewhere";
  s.linkAll = true;
  s.colourKeys = false;
  s.linked = {"shadowmap.size"};
  return s;
}

TEST(ExplorerSettings, SaveAndLoadRoundTripAtomically) {
  LectureTempDir dir;
  const std::string path = (dir.path / "sub" / "settings.json").string();
  saveSettings(path, sampleSettings());
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".tmp")) << "the temporary file must be renamed over the real one";
  const SettingsLoad load = loadSettings(path);
  ASSERT_TRUE(load.settings) << load.problem;
  EXPECT_TRUE(load.problem.empty());
  EXPECT_EQ(settingsToJson(*load.settings), settingsToJson(sampleSettings()));
  EXPECT_DOUBLE_EQ(load.settings->viewports[0].params.at("bias.constant"), 1.25e-5);  // exact, not rounded
  // Saving again replaces the file.
  ExplorerSettings other = sampleSettings();
  other.scene = "basic";
  saveSettings(path, other);
  EXPECT_EQ(loadSettings(path).settings->scene, "basic");
  // No file: no settings and no problem.
  const SettingsLoad none = loadSettings((dir.path / "missing.json").string());
  EXPECT_FALSE(none.settings);
  EXPECT_TRUE(none.problem.empty());
}

TEST(ExplorerSettings, ACorruptFileIsReportedAndSetAsideNeverLost) {
  LectureTempDir dir;
  for (const std::string text :
       {std::string("{\"scene\": \"basic\", \"viewports\": [ {\"preset\": "), std::string("[1, 2, 3]"),
        std::string("{\"ui_scale\": \"big\"}"),
        std::string("{\"viewports\": [{\"params\": {\"shadowmap.size\": 512}}]}"), std::string("\x01\x02\xff")}) {
    const fs::path path = dir.path / "settings.json";
    { std::ofstream(path) << text; }
    const SettingsLoad load = loadSettings(path.string());
    EXPECT_FALSE(load.settings) << text;
    EXPECT_NE(load.problem.find(path.string()), std::string::npos) << load.problem;
    EXPECT_NE(load.problem.find("corrupt"), std::string::npos) << load.problem;
    EXPECT_FALSE(fs::exists(path)) << "the corrupt file must be moved aside";
    // ... and kept, byte for byte, under settings.json.bad-<time>.
    int kept = 0;
    for (const auto& entry : fs::directory_iterator(dir.path)) {
      if (entry.path().filename().string().rfind("settings.json.bad-", 0) != 0) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::stringstream content;
      content << in.rdbuf();
      if (content.str() == text) ++kept;
      fs::remove(entry.path());
    }
    EXPECT_EQ(kept, 1) << text;
  }
}

TEST(ExplorerSettings, OutOfRangeValuesAreClampedNotFatal) {
  ExplorerSettings s = settingsFromJson(R"({"ui_scale": 40, "camera_speed": -3, "scene": "basic"})");
  EXPECT_FLOAT_EQ(s.uiScale, 3.0f);
  EXPECT_FLOAT_EQ(s.cameraSpeed, 0.0f);  // = the default
  EXPECT_THROW(settingsFromJson(R"({"viewports": [{"preset": "a"}, {"preset": "b"}, {"preset": "c"},
                                    {"preset": "d"}, {"preset": "e"}]})"),
               std::runtime_error);
}

TEST(ExplorerSettings, StartLayoutUsesSavedViewportsDropsUnknownOnesAndDefaultsOtherwise) {
  ExplorerSettings saved = sampleSettings();
  saved.viewports.push_back({"no-such-preset", {}, ""});
  saved.viewports.push_back({"standard", {{"no.such.key", 1.0}}, ""});
  ExplorerOptions o;
  std::string problems;
  startLayout(o, &saved, problems);
  EXPECT_EQ(o.scene, "columns");
  EXPECT_EQ(o.technique, "pcf");
  EXPECT_EQ(o.compareTechniques, (std::vector<std::string>{"vsm"}));
  EXPECT_NE(problems.find("no-such-preset"), std::string::npos) << problems;
  EXPECT_NE(problems.find("no.such.key"), std::string::npos) << problems;
  // The saved values reach the technique exactly (enums and bools by name for --set).
  Technique t = makeTechnique(o.technique, o.overrides);
  EXPECT_EQ(t.params.get("shadowmap.size"), 512);
  EXPECT_DOUBLE_EQ(t.params.get("bias.constant"), 1.25e-5);
  EXPECT_EQ(o.enlargedViews.front(), "aliasing");

  // The command line wins over the saved viewports and scene.
  ExplorerOptions given;
  given.technique = "esm";
  given.layoutGiven = given.sceneGiven = true;
  problems.clear();
  startLayout(given, &saved, problems);
  EXPECT_EQ(given.technique, "esm");
  EXPECT_EQ(given.scene, "basic");
  EXPECT_TRUE(given.compareTechniques.empty());

  // Nothing saved and nothing given: the first start compares two techniques with debug views.
  ExplorerOptions first;
  startLayout(first, nullptr, problems);
  EXPECT_TRUE(first.firstStartDefaults);
  EXPECT_EQ(first.compareTechniques.size(), 1u);
  EXPECT_FALSE(first.debugViews.empty());
}

TEST(ExplorerSettings, CaptureRecordsOnlyChangedParameters) {
  ExplorerState state = stateWith({"pcf", "standard"});
  state.sceneLabel = "basic";
  paramsOf(state, 0).set("shadowmap.size", 256);
  state.slots[1].enlargedView = "texels";
  state.uiScale = 1.25f;
  const ExplorerSettings s = captureSettings(state);
  ASSERT_EQ(s.viewports.size(), 2u);
  EXPECT_EQ(s.viewports[0].preset, "pcf");
  EXPECT_EQ(s.viewports[0].params.size(), 1u);
  EXPECT_EQ(s.viewports[0].params.at("shadowmap.size"), 256);
  EXPECT_TRUE(s.viewports[1].params.empty());
  EXPECT_EQ(s.viewports[1].enlargedView, "texels");
  EXPECT_FLOAT_EQ(s.uiScale, 1.25f);
}

// Issue #23: presenter mode cut long captions at a fixed five lines ("...at the largest"). The
// strip now grows to what the text needs (up to kCaptionMaxShare of the window); every step of the
// shipped tours must fit it whole, in presenter mode, at 1280x720 and 1920x1080, with the
// explorer's font.
TEST(ExplorerCaption, EveryShippedStepFitsTheStripInPresenterMode) {
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  applyUiScale(1.0f);
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  io.FontGlobalScale = kPresenterScale;
  io.DeltaTime = 1.0f / 60.0f;
  for (const ImVec2 size : {ImVec2(1280, 720), ImVec2(1920, 1080)}) {
    io.DisplaySize = size;
    ImGui::NewFrame();
    float tallest = 0.0f;
    for (const char* name : {"survey", "pixel-correct", "filtering"}) {
      const Tour tour = loadTour(std::string(SHADOWLAB_SOURCE_DIR) + "/tours/" + name + ".json");
      for (const TourStep& s : tour.steps) {
        const bool staged = s.frames.size() > 1 || (s.frames.size() == 1 && s.frames[0] > 1);
        const float needed = captionStripHeight(s, size.x, staged);
        tallest = std::max(tallest, needed);
        EXPECT_LE(needed, size.y * kCaptionMaxShare) << name << " \"" << s.title << "\" at " << size.x << "x" << size.y;
      }
    }
    // The strip before: five lines whatever the text. Some step needs more (it was cut).
    const float fiveLines = ImGui::GetFontSize() * 5.0f * 1.25f + 2.0f * ImGui::GetStyle().WindowPadding.y;
    EXPECT_GT(tallest, fiveLines) << "at " << size.x << "x" << size.y;
    ImGui::EndFrame();
  }
  ImGui::DestroyContext();
}

TEST(ExplorerColourKeys, EveryHeatMapViewHasAKeyThatSaysWhatBlackMeans) {
  for (const char* view : {"aliasing", "confidence", "history", "disocclusion", "lightspace", "error", "shadowmap",
                           "visibility", "texels", "cascades"}) {
    const ColourKey* key = viewColourKey(view);
    ASSERT_NE(key, nullptr) << view;
    EXPECT_FALSE(key->title.empty()) << view;
    EXPECT_TRUE(!key->stops.empty() || !key->specials.empty()) << view;
    float last = -1.0f;
    for (const ColourStop& s : key->stops) {
      EXPECT_GT(s.position, last) << view;
      EXPECT_FALSE(s.label.empty()) << view;
      last = s.position;
    }
    if (!key->stops.empty()) {
      EXPECT_FLOAT_EQ(key->stops.front().position, 0.0f) << view;
      EXPECT_FLOAT_EQ(key->stops.back().position, 1.0f) << view;
    }
  }
  // The error view's black (the issue: its tooltip never said what black means).
  bool black = false;
  for (const SpecialColour& s : viewColourKey("error")->specials)
    black |= s.colour == glm::vec3(0.0f) && s.meaning.find("black") != std::string::npos;
  EXPECT_TRUE(black);
  EXPECT_EQ(viewColourKey("no-such-view"), nullptr);
}

// The aliasing key and the shader must agree: the key's ends are 2^range px/texel and the
// shader divides log2 by the same range, with the same five colours.
// A thumbnail's key prints its last label with the unit: never the unit twice ("64+ samples
// samples" under izb-lists, "32 texels (pcss.max_radius) texels" under penumbra before
// labelWithUnit).
TEST(ExplorerColourKeys, EndLabelsNameTheirUnitOnce) {
  EXPECT_EQ(labelWithUnit("64+ samples", "samples"), "64+ samples");
  EXPECT_EQ(labelWithUnit("64", "samples"), "64 samples");
  EXPECT_EQ(labelWithUnit("1", ""), "1");
  EXPECT_EQ(labelWithUnit("8 nodes (deep.nodes)", "nodes"), "8 nodes (deep.nodes)");
  for (const std::string& view : viewsWithColourKeys()) {
    const ColourKey* key = viewColourKey(view);
    ASSERT_NE(key, nullptr) << view;
    if (key->stops.empty() || key->unit.empty()) continue;
    const std::string& label = key->stops.back().label;
    const std::string end = labelWithUnit(label, key->unit);
    EXPECT_NE(end.find(key->unit), std::string::npos) << view << ": " << end;
    if (label.find(key->unit) != std::string::npos) EXPECT_EQ(end, label) << view;
  }
}

TEST(ExplorerColourKeys, AliasingKeyMatchesTheShader) {
  const ColourKey& key = *viewColourKey("aliasing");
  ASSERT_EQ(key.stops.size(), 5u);
  EXPECT_EQ(key.stops.back().label, std::to_string(int(std::exp2(kAliasingLog2Range))));
  EXPECT_EQ(key.stops.front().label, "1/" + std::to_string(int(std::exp2(kAliasingLog2Range))));
  EXPECT_EQ(key.stops[2].label, "1");
  std::ifstream in(fs::path(SHADOWLAB_SOURCE_DIR) / "shaders/views/aliasing.frag");
  std::stringstream text;
  text << in.rdbuf();
  const std::string shader = text.str();
  char range[32];
  std::snprintf(range, sizeof range, "log2(pixelsPerTexel) / %.1f", kAliasingLog2Range);
  EXPECT_NE(shader.find(range), std::string::npos) << "shader's range differs from kAliasingLog2Range";
  for (const ColourStop& s : key.stops) {
    char colour[64];
    std::snprintf(colour, sizeof colour, "vec3(%.2f, %.2f, %.2f)", s.colour.r, s.colour.g, s.colour.b);
    EXPECT_NE(shader.find(colour), std::string::npos) << colour;
  }
  // Sampling between stops interpolates; outside clamps.
  EXPECT_EQ(sampleColourKey(key, 0.5f), key.stops[2].colour);
  EXPECT_EQ(sampleColourKey(key, 2.0f), key.stops.back().colour);
  const glm::vec3 mid = sampleColourKey(key, 0.625f);
  EXPECT_NEAR(mid.r, 0.5f * (key.stops[2].colour.r + key.stops[3].colour.r), 1e-6f);
}

TEST(ExplorerExports, ScreenshotFolderIsOutsideTheWorkingDirectory) {
  EXPECT_EQ(defaultScreenshotDir([](const char* n) -> const char* {
              return std::string(n) == "XDG_PICTURES_DIR" ? "/pics" : "/home/u";
            }),
            "/pics/shadowlab");
  EXPECT_EQ(
      defaultScreenshotDir([](const char* n) -> const char* { return std::string(n) == "HOME" ? "/home/u" : nullptr; }),
      "/home/u/Pictures/shadowlab");
  EXPECT_EQ(defaultScreenshotDir([](const char*) -> const char* { return nullptr; }), "/tmp/shadowlab");
  EXPECT_TRUE(fs::path(defaultScreenshotDir()).is_absolute());
}

TEST(ExplorerExports, TextFilesAreWrittenWithTheirFullPathAndBadFoldersNamed) {
  LectureTempDir dir;
  const std::string path = writeTextFile((dir.path / "new").string(), "a.csv", "x,y\n");
  EXPECT_EQ(path, (dir.path / "new" / "a.csv").string());
  EXPECT_TRUE(fs::exists(path));
  { std::ofstream(dir.path / "file") << "not a folder"; }
  try {
    writeTextFile((dir.path / "file" / "sub").string(), "a.csv", "x");
    FAIL() << "writing below a file must fail";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir.path / "file").string()), std::string::npos) << e.what();
  }
}

TEST(ExplorerExports, ChartCsvAndSvgHoldEveryPoint) {
  std::vector<ChartPoint> points;
  recordChartPoint(points, {"pcf {shadowmap.size=512, bias.mode=slope}", 2.0, 5.0, 0, 4.0, {}});
  recordChartPoint(points, {"vsm \"quoted\"", 3.0, 1.0, 1, 0.5, {}});
  const std::string csv = chartPointsCsv(points);
  EXPECT_NE(csv.find("\"pcf {shadowmap.size=512, bias.mode=slope}\",2,1,5,4,yes"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\"vsm \"\"quoted\"\"\""), std::string::npos) << csv;
  const std::string svg = chartPointsSvg(points);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  size_t circles = 0;
  for (size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
  EXPECT_EQ(circles, 2u);
  EXPECT_NE(svg.find("&quot;quoted&quot;"), std::string::npos);
  EXPECT_NE(chartPointsSvg({}).find("</svg>"), std::string::npos);  // empty chart: still a valid file
}

TEST(ExplorerShortcuts, HelpListsTheKeysAndUiScaleIsClamped) {
  std::string keys;
  for (const Shortcut& s : explorerShortcuts()) keys += s.keys + "|";
  for (const char* k : {"F1", "Ctrl + =", "Tab", "F12", "P", "N", "K", "hold M", "mouse wheel"})
    EXPECT_NE(keys.find(k), std::string::npos) << k;
  EXPECT_FLOAT_EQ(steppedUiScale(1.0f, 1), 1.125f);
  EXPECT_FLOAT_EQ(steppedUiScale(1.0f, -1), 0.875f);
  EXPECT_FLOAT_EQ(steppedUiScale(2.4f, 5), kMaxUiScale);
  EXPECT_FLOAT_EQ(steppedUiScale(0.8f, -5), kMinUiScale);
}

TEST(ExplorerCamera, SpeedIsAShareOfTheSceneSize) {
  Camera c;
  c.position = glm::vec3(0, 1, 5);
  c.target = glm::vec3(0);
  FlyCamera small, large;
  small.jumpTo(c, 2.0f);
  large.jumpTo(c, 2000.0f);
  EXPECT_FLOAT_EQ(large.speed() / small.speed(), 1000.0f);
  EXPECT_LT(small.speed(), 2.0f * 0.1f) << "crossing the scene must take seconds, not one";
  small.update(FlyInput{.scrollSteps = 2.0f}, 0.016f);
  EXPECT_NEAR(small.speedFactor(), FlyCamera::kDefaultSpeedFactor * 1.5625f, 1e-6f);
  small.setSpeedFactor(1e9f);
  EXPECT_FLOAT_EQ(small.speedFactor(), FlyCamera::kMaxSpeedFactor);
  small.setSpeedFactor(std::nanf(""));
  EXPECT_FLOAT_EQ(small.speedFactor(), FlyCamera::kMaxSpeedFactor);
  small.jumpTo(c, std::nanf(""));
  EXPECT_TRUE(std::isfinite(small.speed()));
}

// A layout other than the preset's (technique.layout) survives settings by name, with the values
// of that layout's own parameters, and a panel edit of it rebuilds the viewport's technique.
TEST(ExplorerSettings, AChosenLayoutIsSavedByNameAndRestoredWithItsParameters) {
  ExplorerState state = stateWith({"pixel-correct", "standard"});
  state.sceneLabel = "basic";
  paramsOf(state, 0).setFromString(kLayoutParam, "cascaded");
  EXPECT_EQ(applyCompositionChanges(state), 1);
  ASSERT_EQ(state.slots[0].viewport->technique.layout->id(), "cascaded");
  EXPECT_EQ(state.slots[0].viewport->technique.accumulation->id(), "pixel-correct");
  paramsOf(state, 0).set("cascades.count", 2);
  const ExplorerSettings s = captureSettings(state);
  EXPECT_EQ(s.viewports[0].layout, "cascaded");
  EXPECT_EQ(s.viewports[0].params.count(kLayoutParam), 0u);  // by name, never by index
  EXPECT_EQ(s.viewports[1].layout, "");
  const ExplorerSettings loaded = settingsFromJson(settingsToJson(s));
  ExplorerOptions o;
  std::string problems;
  startLayout(o, &loaded, problems);
  EXPECT_TRUE(problems.empty()) << problems;
  const Technique t = makeTechnique(o.technique, o.overrides);
  EXPECT_EQ(t.layout->id(), "cascaded");
  EXPECT_EQ(t.params.i("cascades.count"), 2);
  EXPECT_EQ(applyCompositionChanges(state), 0);  // nothing changed since
}

}  // namespace
}  // namespace sl
