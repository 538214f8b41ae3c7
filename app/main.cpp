// shadowlab: the explorer window when run without a subcommand, headless tools otherwise.
#include "cli/args.h"
#include "cli/commands.h"
#include "explorer/explorer.h"
#include "explorer/settings.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>

namespace {

const char* kUsage =
    "shadowlab - explore, compare and measure shadow-mapping techniques\n"
    "\n"
    "  shadowlab [--scene S] [--technique T] [--set key=value]... [--camera NAME] [--size WxH]\n"
    "            [--compare T2]... [--view NAME]... [--magnifier] [--visibility-plot] [--dpds-plot]\n"
    "            [--light AZ,EL]\n"
    "            [--enlarge VIEW]... [--ui-scale S] [--show-help] [--settings FILE | --no-settings]\n"
    "            [--save-to DIR] [--save-on-exit]               (captures: window, each viewport, CSV, SVG)\n"
    "            [--soak SECONDS]                               (unattended reliability run: scripts/soak.sh)\n"
    "            [--frames N] [--screenshot-on-exit F.png]      open the explorer window\n"
    "  shadowlab --tour T.json [--tour-step N] [--presenter]    play a lecture tour (arrows/PageUp/PageDown, F5)\n"
    "            [--monitor N]                                  presenter mode fills the window's display, or N\n"
    "  shadowlab render --scene S --technique T --out F.png ...  render headless (see render --help)\n"
    "  shadowlab list                                           techniques, parameters, views, scenes\n"
    "  shadowlab reference --scene S --out F.png ...            ray-traced shadow truth (see reference --help)\n"
    "  shadowlab bench --scene S --techniques a,b --json F ...  time and error vs. the reference (bench --help)\n"
    "  shadowlab plot --scene S --techniques a,b --out F.svg    visibility vs receiver depth at a texel (plot --help)\n"
    "  shadowlab plot dpds --scene S --out F.svg ...            perspective aliasing along the view (plot --help)\n"
    "  shadowlab figure --tour T --step N --out F.png           a lecture-tour step as a figure (figure --help)\n"
    "\n"
    "Shaders are read at run time from $SHADOWLAB_SHADERS (default: the source tree's shaders/).\n"
    "The window keeps its settings in $SHADOWLAB_SETTINGS or $XDG_CONFIG_HOME/shadowlab/settings.json\n"
    "(not with --frames unless --settings is given). F1 in the window lists every key.\n";

int runExplorerCommand(int argc, char** argv) {
  sl::Args args(argc, argv, 1,
                {"--scene", "--technique", "--set", "--camera", "--size", "--frames", "--screenshot-on-exit",
                 "--shaders", "--compare", "--view", "--light", "--tour", "--tour-step", "--settings", "--enlarge",
                 "--ui-scale", "--soak", "--save-to", "--monitor"},
                {"--magnifier", "--visibility-plot", "--dpds-plot", "--presenter", "--no-settings", "--show-help",
                 "--save-on-exit"});
  sl::ExplorerOptions o;
  o.scene = args.get("--scene", o.scene);
  o.technique = args.get("--technique", o.technique);
  o.overrides = args.all("--set");
  o.camera = args.get("--camera");
  args.getSize("--size", o.width, o.height);
  o.maxFrames = args.getInt("--frames", 0);
  o.screenshotOnExit = args.get("--screenshot-on-exit");
  o.shaderDir = args.get("--shaders");
  o.compareTechniques = args.all("--compare");  // more viewports, side by side, same camera
  o.debugViews = args.all("--view");
  o.magnifier = args.has("--magnifier");
  o.visibilityPlot = args.has("--visibility-plot");
  o.dpdsPlot = args.has("--dpds-plot");
  o.tour = args.get("--tour");  // its steps replace --scene, --technique and the views
  o.tourStep = args.getInt("--tour-step", 1);
  o.presenter = args.has("--presenter");
  if (args.has("--monitor")) {
    o.monitor = args.getInt("--monitor", 0);
    if (o.monitor < 1)
      throw sl::ArgError("--monitor: expected a display number from 1, got '" + args.get("--monitor") + "'");
  }
  o.showHelp = args.has("--show-help");
  o.saveOnExit = args.has("--save-on-exit");
  o.screenshotDir = args.get("--save-to");
  if (args.has("--soak")) {
    o.soakSeconds = args.getInt("--soak", 0);
    if (o.soakSeconds <= 0) throw sl::ArgError("--soak: expected a number of seconds > 0");
  }
  if (args.has("--ui-scale")) {
    char* end = nullptr;
    const std::string v = args.get("--ui-scale");
    o.uiScale = std::strtof(v.c_str(), &end);
    if (v.empty() || *end || !(o.uiScale >= 0.75f && o.uiScale <= 2.5f))
      throw sl::ArgError("--ui-scale: expected a number in [0.75, 2.5], got '" + v + "'");
  }
  o.enlargedViews = args.all("--enlarge");  // one per viewport, in order ("colour" = none)
  for (std::string& v : o.enlargedViews)
    if (v == "colour" || v == "color") v.clear();
  // Settings: an explicit file always; otherwise the user's file, except in scripted runs
  // (--frames), which must not depend on (or change) what a person left there.
  o.sceneGiven = args.has("--scene");
  o.layoutGiven = args.has("--technique") || args.has("--compare") || args.has("--view") || args.has("--set") ||
                  args.has("--enlarge") || args.has("--tour");
  if (args.has("--settings"))
    o.settingsPath = args.get("--settings");
  else if (!args.has("--no-settings") && o.maxFrames == 0 && o.soakSeconds == 0)
    o.settingsPath = sl::defaultSettingsPath();
  if (args.has("--light")) {
    // Degrees: azimuth about +y from +z and elevation of the direction towards the light.
    const std::string v = args.get("--light");
    float az = 0, el = 0;
    char extra = 0;
    if (std::sscanf(v.c_str(), "%f,%f%c", &az, &el, &extra) != 2 || !std::isfinite(az) || !std::isfinite(el) ||
        el < -90.0f || el > 90.0f)
      throw sl::ArgError("--light: expected AZ,EL in degrees with EL in [-90,90], got '" + v + "'");
    o.lightAngles = glm::vec2(az, el);
    o.setLight = true;
  }
  return sl::runExplorer(o);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc >= 2) {
      std::string cmd = argv[1];
      if (cmd == "render") return sl::runRenderCommand(argc, argv);
      if (cmd == "list") return sl::runListCommand(argc, argv);
      if (cmd == "reference") return sl::runReferenceCommand(argc, argv);
      if (cmd == "bench") return sl::runBenchCommand(argc, argv);
      if (cmd == "plot") return sl::runPlotCommand(argc, argv);
      if (cmd == "figure") return sl::runFigureCommand(argc, argv);
      if (cmd == "help" || cmd == "--help" || cmd == "-h") {
        std::cout << kUsage;
        return 0;
      }
      if (cmd.rfind("--", 0) != 0) {
        std::cerr << "shadowlab: unknown command '" << cmd << "'\n\n" << kUsage;
        return 1;
      }
    }
    return runExplorerCommand(argc, argv);
  } catch (const sl::ArgError& e) {
    std::cerr << "shadowlab: " << e.what() << "\n\n" << kUsage;
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "shadowlab: " << e.what() << "\n";
    return 1;
  }
}
