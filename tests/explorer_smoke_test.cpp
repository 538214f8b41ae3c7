// Runs the real program's interactive window for a few frames under a virtual X server, and
// checks the no-display path. These are end-to-end: they catch context creation, ImGui setup
// and renderer wiring problems that unit tests of the parts cannot.
#include "explorer/settings.h"
#include "explorer/side_panel.h"
#include "sanitizer_report.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

CommandResult runCommand(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  // The explorer's own status where explorerUnderXvfb printed it, not xvfb-run's.
  const std::string marker = "[explorer exit status ";
  const size_t at = result.output.rfind(marker);
  if (at != std::string::npos) result.exitCode = std::atoi(result.output.c_str() + at + marker.size());
  sl::test::expectNoSanitizerReport(result.output, command);
  return result;
}

std::string shellQuote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// The explorer with `args` under `timeout` and `xvfb-run` on one screen of `screen` (WxHxD), its
// own exit status printed last, which runCommand reports: xvfb-run now and then fails to remove
// its temporary folder after the program ended (exit 5, "problem while cleaning up temporary
// directory"), which says nothing of the explorer.
std::string explorerUnderXvfb(int timeoutSeconds, const std::string& screen, const std::string& args) {
  const std::string program = shellQuote(SHADOWLAB_BINARY) + " " + args + "; echo \"[explorer exit status $?]\"";
  return "timeout " + std::to_string(timeoutSeconds) + " xvfb-run -a -s " + shellQuote("-screen 0 " + screen) +
         " sh -c " + shellQuote(program);
}

bool onPath(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

// Variance of the grey level over a rectangle of an RGB image.
double greyVariance(const unsigned char* rgb, int width, int x0, int y0, int x1, int y1) {
  double sum = 0, sumSquares = 0;
  long count = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const unsigned char* p = rgb + (size_t(y) * width + x) * 3;
      const double grey = (p[0] + p[1] + p[2]) / 3.0;
      sum += grey;
      sumSquares += grey * grey;
      ++count;
    }
  if (count == 0) return 0;
  const double mean = sum / count;
  return sumSquares / count - mean * mean;
}

}  // namespace

TEST(ExplorerSmoke, DrawsFramesUnderXvfbAndWritesAScreenshot) {
  if (!onPath("xvfb-run")) GTEST_SKIP() << "xvfb-run is not on PATH (apt install xvfb); explorer not run";
  const auto dir = std::filesystem::temp_directory_path() / ("shadowlab-explorer-smoke-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string shot = (dir / "shot.png").string();

  const std::string command =
      explorerUnderXvfb(240, "1280x800x24", "--frames 5 --screenshot-on-exit " + shellQuote(shot));
  const CommandResult result = runCommand(command);
  ASSERT_EQ(result.exitCode, 0) << command << "\n" << result.output;
  ASSERT_TRUE(std::filesystem::exists(shot)) << result.output;

  int width = 0, height = 0, channels = 0;
  unsigned char* rgb = stbi_load(shot.c_str(), &width, &height, &channels, 3);
  ASSERT_NE(rgb, nullptr) << "could not read " << shot;
  EXPECT_GE(width, 640);
  EXPECT_GE(height, 360);
  // The whole window (panel text on a dark background) must not be one colour ...
  const double windowVariance = greyVariance(rgb, width, 0, 0, width, height);
  // ... and neither may the viewport area right of the side panel, where the scene is drawn.
  const int areaLeft = std::min(width - 1, int(sl::kSidePanelWidth) + 16);
  const double viewportVariance = greyVariance(rgb, width, areaLeft, 40, width - 8, height - 8);
  stbi_image_free(rgb);
  EXPECT_GT(windowVariance, 10.0);
  EXPECT_GT(viewportVariance, 10.0) << "the rendered scene looks uniform";
  std::filesystem::remove_all(dir);
}

TEST(ExplorerSmoke, WithoutADisplayExplainsHowToRenderHeadless) {
  const std::string command =
      "env -u DISPLAY -u WAYLAND_DISPLAY timeout 60 " + std::string(shellQuote(SHADOWLAB_BINARY));
  const CommandResult result = runCommand(command);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("no display"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("shadowlab render"), std::string::npos) << result.output;
}

TEST(ExplorerSmoke, BadLightAnglesAreRejectedBeforeOpeningAWindow) {
  for (const char* value : {"200,x", "10", "10,95", "nan,10"}) {
    const std::string command = "env -u DISPLAY -u WAYLAND_DISPLAY timeout 60 " +
                                std::string(shellQuote(SHADOWLAB_BINARY)) + " --light " + shellQuote(value);
    const CommandResult result = runCommand(command);
    EXPECT_EQ(result.exitCode, 1) << value << "\n" << result.output;
    EXPECT_NE(result.output.find("--light"), std::string::npos) << result.output;
  }
}

// The "hot reload of the accumulation shader keeps the explorer running", end to end:
// the window runs pixel-correct from a copy of the shaders, the update shader is broken while it
// runs (the error is reported with file:line), then fixed, and the window keeps drawing to the
// last frame.
TEST(ExplorerSmoke, BrokenAccumulationShaderKeepsTheWindowRunning) {
  if (!onPath("xvfb-run")) GTEST_SKIP() << "xvfb-run is not on PATH (apt install xvfb); explorer not run";
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("shadowlab-explorer-reload-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy(fs::path(SHADOWLAB_SOURCE_DIR) / "shaders", dir / "shaders", fs::copy_options::recursive);
  const fs::path frag = dir / "shaders" / "accumulation" / "pixel_correct.frag";
  const std::string shot = (dir / "shot.png").string();
  // Break at 4 s (shaders are built by then), restore at 7 s; ~500 frames at 640x360 last longer.
  const std::string script =
      "(sleep 4; cp " + shellQuote(frag.string()) + " " + shellQuote(frag.string() + ".good") +
      "; printf 'x+;\\n' >> " + shellQuote(frag.string()) + "; sleep 3; cp " + shellQuote(frag.string() + ".good") +
      " " + shellQuote(frag.string()) + ") & " +
      explorerUnderXvfb(240, "1280x800x24",
                        "--technique pixel-correct --size 640x360 --frames 500 --shaders " +
                            shellQuote((dir / "shaders").string()) + " --screenshot-on-exit " + shellQuote(shot)) +
      "; status=$?; wait; exit $status";
  const CommandResult result = runCommand("sh -c " + shellQuote(script));
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("pixel_correct.frag:"), std::string::npos)
      << "the broken shader was not reported with its file (did the run end before 4 s?)\n"
      << result.output;
  int width = 0, height = 0, channels = 0;
  unsigned char* rgb = stbi_load(shot.c_str(), &width, &height, &channels, 3);
  ASSERT_NE(rgb, nullptr) << "no screenshot: " << result.output;
  const int areaLeft = std::min(width - 1, int(sl::kSidePanelWidth) + 16);
  EXPECT_GT(greyVariance(rgb, width, areaLeft, 40, width - 8, height - 8), 10.0) << "the scene is not drawn";
  stbi_image_free(rgb);
  fs::remove_all(dir);
}

// Settings between runs, end to end: a run with an explicit settings file writes it (scene,
// viewports, changed parameters); the next run without viewport flags restores them; a corrupt
// file is reported on stderr, set aside as settings.json.bad-<time>, and the window still runs.
TEST(ExplorerSmoke, SettingsPersistAndACorruptFileIsSetAside) {
  if (!onPath("xvfb-run")) GTEST_SKIP() << "xvfb-run is not on PATH (apt install xvfb); explorer not run";
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("shadowlab-explorer-settings-" + std::to_string(getpid()));
  fs::remove_all(dir);
  const std::string settings = (dir / "config" / "settings.json").string();
  const std::string base = "--size 640x360 --frames 3 --settings " + shellQuote(settings);
  auto explorer = [&](const std::string& args) { return runCommand(explorerUnderXvfb(240, "1280x720x24", args)); };
  CommandResult first = explorer(base + " --scene columns --technique vsm --set shadowmap.size=512 --view shadowmap");
  ASSERT_EQ(first.exitCode, 0) << first.output;
  ASSERT_TRUE(fs::exists(settings)) << first.output;
  const sl::SettingsLoad saved = sl::loadSettings(settings);
  ASSERT_TRUE(saved.settings) << saved.problem;
  EXPECT_EQ(saved.settings->scene, "columns");
  ASSERT_EQ(saved.settings->viewports.size(), 1u);
  EXPECT_EQ(saved.settings->viewports[0].preset, "vsm");
  EXPECT_EQ(saved.settings->viewports[0].params.at("shadowmap.size"), 512);

  // Restored: the window title names the scene, and it exits cleanly; a saved view the
  // technique no longer offers would not be fatal either.
  CommandResult second = explorer(base + " --screenshot-on-exit " + shellQuote((dir / "shot.png").string()));
  EXPECT_EQ(second.exitCode, 0) << second.output;
  EXPECT_EQ(sl::loadSettings(settings).settings->viewports[0].preset, "vsm") << "a plain start changed them";

  { std::ofstream(settings) << "{\"viewports\": [ oops"; }
  CommandResult corrupt = explorer(base);
  EXPECT_EQ(corrupt.exitCode, 0) << corrupt.output;
  EXPECT_NE(corrupt.output.find("is corrupt"), std::string::npos) << corrupt.output;
  int setAside = 0;
  for (const auto& entry : fs::directory_iterator(dir / "config"))
    setAside += entry.path().filename().string().rfind("settings.json.bad-", 0) == 0;
  EXPECT_EQ(setAside, 1);
  fs::remove_all(dir);
}

// A short soak (scripts/soak.sh runs it for minutes): presets, scenes, viewport counts and
// views switch, a shader in a copy is broken and fixed, and the run reports RSS and passes.
TEST(ExplorerSmoke, ShortSoakRecoversFromABrokenShaderAndReportsMemory) {
  if (!onPath("xvfb-run")) GTEST_SKIP() << "xvfb-run is not on PATH (apt install xvfb); explorer not run";
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("shadowlab-explorer-soak-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy(fs::path(SHADOWLAB_SOURCE_DIR) / "shaders", dir / "shaders", fs::copy_options::recursive);
  const std::string shading = (dir / "shaders" / "common" / "shading.glsl").string();
  std::ifstream before(shading);
  const std::string original((std::istreambuf_iterator<char>(before)), std::istreambuf_iterator<char>());
  const std::string command = explorerUnderXvfb(
      300, "1280x720x24", "--soak 15 --size 640x360 --no-settings --shaders " + shellQuote((dir / "shaders").string()));
  const CommandResult result = runCommand(command);
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("soak: PASSED"), std::string::npos) << result.output;
  // 15 s is less than one cycle through every preset and scene, so growth is not judged here
  // (scripts/soak.sh is); the report must say so rather than pass it silently.
  EXPECT_NE(result.output.find("growth not judged"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("shading.glsl:"), std::string::npos) << "the broken shader was never reported";
  std::ifstream after(shading);
  const std::string restored((std::istreambuf_iterator<char>(after)), std::istreambuf_iterator<char>());
  EXPECT_EQ(restored, original) << "the soak left the shader copy broken";
  fs::remove_all(dir);
}

// Real X key events (xdotool through the XTEST extension) into the real window: the shortcuts
// act on what a lecturer sees. Each key is a quick tap, shorter than one llvmpipe frame, which
// ImGui 1.86's key state alone would miss (explorer/shortcuts.h). The program prints what the
// keys left behind when it ends (Ctrl+Q) and F12 writes the window into --save-to.
TEST(ExplorerSmoke, RealKeyEventsDriveShortcutsAndTourStages) {
  if (!onPath("xvfb-run") || !onPath("xdotool"))
    GTEST_SKIP() << "xvfb-run or xdotool is not on PATH (apt install xvfb xdotool); explorer not run";
  const std::string dir = testing::TempDir() + "shadowlab-keys-" + std::to_string(getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string log = dir + "/explorer.log";
  // Step 4 of the pixel-correct tour captures 1, 20, 40 and 60 still frames: PageDown goes from
  // the first count to the second before it would leave the step.
  const std::string explorer = shellQuote(SHADOWLAB_BINARY) + " --tour tours/pixel-correct.json --tour-step 4" +
                               " --size 800x450 --frames 100000 --no-settings --save-to " + shellQuote(dir) + " >" +
                               shellQuote(log) + " 2>&1 &";
  const std::string keys =
      "pid=$!; wid=$(timeout 60 xdotool search --sync --onlyvisible --name 'shadowlab explorer' | head -n1); "
      "[ -n \"$wid\" ] || { echo 'no explorer window'; kill $pid; exit 1; }; "
      "xdotool mousemove --window \"$wid\" 600 150; xdotool windowfocus --sync \"$wid\" || true; sleep 2; "
      "for k in 4 ctrl+equal k p F1 Next F12; do xdotool key \"$k\"; sleep 1; done; "
      "sleep 1; xdotool key ctrl+q; wait $pid; echo \"explorer exit $?\"";
  const CommandResult r =
      runCommand("timeout 240 xvfb-run -a -s '-screen 0 1280x720x24' sh -c " + shellQuote(explorer + " " + keys));
  std::ifstream in(log);
  const std::string output((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  sl::test::expectNoSanitizerReport(output, "explorer under xdotool");
  ASSERT_NE(r.output.find("explorer exit 0"), std::string::npos) << r.output << output;
  const size_t at = output.find("explorer: state ");
  ASSERT_NE(at, std::string::npos) << output;
  const std::string state = output.substr(at, output.find('\n', at) - at);
  for (const char* expected :
       {"viewports=4", "ui_scale=1.125", "paused=1", "colour_keys=0", "help=1", "tour_step=4", "tour_frames=20"})
    EXPECT_NE(state.find(expected), std::string::npos) << expected << " not in: " << state;
  bool windowShot = false;  // F12: the window (Shift+F12, not pressed, would add one PNG per viewport)
  for (const auto& e : std::filesystem::directory_iterator(dir)) windowShot |= e.path().extension() == ".png";
  EXPECT_TRUE(windowShot) << "F12 wrote no window PNG into " << dir;
  std::filesystem::remove_all(dir);
}

// Issue #26: Return did not close a Ctrl+click edit box. Dear ImGui 1.86 reads keys as held
// state at each frame, so a tap that fell between two frames (12 fps on llvmpipe) was lost; the
// recorder now holds a release back until ImGui has seen the key down. Ctrl+click bias.slope of
// viewport 1 (its slider at 138,643 of the 1280x720 window with default settings), type 3,
// Return: the box closes (Ctrl+Q then quits; an open box would take it as text) and the value
// reaches the parameters (the settings file written on exit).
TEST(ExplorerSmoke, ReturnClosesACtrlClickEditBoxAtALowFrameRate) {
  if (!onPath("xvfb-run") || !onPath("xdotool"))
    GTEST_SKIP() << "xvfb-run or xdotool is not on PATH (apt install xvfb xdotool); explorer not run";
  const std::string dir = testing::TempDir() + "shadowlab-return-" + std::to_string(getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string settings = dir + "/settings.json", log = dir + "/explorer.log";
  const std::string explorer = shellQuote(SHADOWLAB_BINARY) + " --size 1280x720 --frames 100000 --settings " +
                               shellQuote(settings) + " >" + shellQuote(log) + " 2>&1 &";
  const std::string keys =
      "pid=$!; wid=$(timeout 60 xdotool search --sync --onlyvisible --name 'shadowlab explorer' | head -n1); "
      "[ -n \"$wid\" ] || { echo 'no explorer window'; kill $pid; exit 1; }; "
      "xdotool mousemove --window \"$wid\" 600 150; xdotool windowfocus --sync \"$wid\" || true; sleep 2; "
      "xdotool mousemove --window \"$wid\" 138 643; sleep 0.5; "
      "xdotool keydown ctrl; xdotool click 1; xdotool keyup ctrl; sleep 0.5; xdotool type 3; sleep 0.5; "
      "xdotool key Return; sleep 1; xdotool mousemove --window \"$wid\" 600 300; sleep 0.5; "
      "xdotool key ctrl+q; sleep 5; kill $pid 2>/dev/null && echo 'still running'; wait $pid; echo \"explorer exit "
      "$?\"";
  const CommandResult r =
      runCommand("timeout 180 xvfb-run -a -s '-screen 0 1280x720x24' sh -c " + shellQuote(explorer + " " + keys));
  std::ifstream in(log);
  const std::string output((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(r.output.find("still running"), std::string::npos) << "Ctrl+Q was typed into the box: Return left it open\n"
                                                               << r.output << output;
  ASSERT_NE(r.output.find("explorer exit 0"), std::string::npos) << r.output << output;
  std::ifstream saved(settings);
  const std::string text((std::istreambuf_iterator<char>(saved)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"bias.slope\": 3"), std::string::npos) << "bias.slope=3 not in the settings: " << text;
  std::filesystem::remove_all(dir);
}

// Issue #23: presenter mode stayed a 1280x720 window in the corner of a 1920x1080 screen. It now
// fills the display the window is on (here Xvfb's one screen), and a --monitor past the last
// display is a clear error before any window opens.
TEST(ExplorerSmoke, PresenterModeFillsTheDisplay) {
  if (!onPath("xvfb-run")) GTEST_SKIP() << "xvfb-run is not on PATH (apt install xvfb); explorer not run";
  const auto dir = std::filesystem::temp_directory_path() / ("shadowlab-presenter-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string shot = (dir / "shot.png").string();
  const std::string tour = std::string(SHADOWLAB_SOURCE_DIR) + "/tours/pixel-correct.json";
  const std::string command = explorerUnderXvfb(
      240, "1600x900x24",
      "--no-settings --tour " + shellQuote(tour) + " --presenter --frames 6 --screenshot-on-exit " + shellQuote(shot));
  const CommandResult result = runCommand(command);
  ASSERT_EQ(result.exitCode, 0) << command << "\n" << result.output;
  int width = 0, height = 0, channels = 0;
  unsigned char* rgb = stbi_load(shot.c_str(), &width, &height, &channels, 3);
  ASSERT_NE(rgb, nullptr) << "could not read " << shot;
  stbi_image_free(rgb);
  EXPECT_EQ(width, 1600);
  EXPECT_EQ(height, 900);
  const CommandResult bad = runCommand(explorerUnderXvfb(
      60, "1280x1024x24", "--no-settings --tour " + shellQuote(tour) + " --presenter --monitor 3 --frames 2"));
  EXPECT_EQ(bad.exitCode, 1) << bad.output;
  EXPECT_NE(bad.output.find("--monitor 3: this display has 1 monitor"), std::string::npos) << bad.output;
  std::filesystem::remove_all(dir);
}
