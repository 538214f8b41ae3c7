// `shadowlab plot`: visibility against receiver depth at the shadow-map texel under one screen
// pixel, for pre-filtered techniques, as an SVG (plot/visibility_plot_data.h makes the curves).
#include "cli/args.h"
#include "cli/commands.h"
#include "gl/gl_util.h"
#include "gl/headless_context.h"
#include "gl/shader_library.h"
#include "plot/visibility_plot_data.h"

#include <algorithm>
#include <iostream>
#include <sstream>

namespace sl {

namespace {

const char* kPlotUsage =
    "usage: shadowlab plot --scene S --techniques a,b,... [--set key=value]... [--camera NAME] [--size WxH]\n"
    "                      [--pixel X,Y] [--range LO,HI] [--samples N] --out F.svg\n"
    "  every technique must be pre-filtered (vsm, esm, evsm2, evsm4, gaussian, ewgf, msm, msm16, convolution);\n"
    "  X,Y: screen pixel from the bottom left (default: the centre); LO,HI: receiver depths shown (0,1).\n"
    "       shadowlab plot dpds --help   the layouts' perspective aliasing (dp/ds) along the view\n";

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, sep);)
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace

int runPlotCommand(int argc, char** argv) {
  // `plot dpds` is the layouts' perspective-aliasing plot (plot_dpds_command.cpp).
  if (argc >= 3 && std::string(argv[2]) == "dpds") return runPlotDpdsCommand(argc, argv);
  for (int i = 2; i < argc; ++i)
    if (std::string(argv[i]) == "--help") {
      std::cout << kPlotUsage;
      return 0;
    }
  try {
    Args args(argc, argv, 2,
              {"--scene", "--techniques", "--set", "--camera", "--size", "--pixel", "--range", "--samples", "--out"});
    if (!args.has("--out")) throw ArgError("--out F.svg is required");
    int width = 640, height = 360;
    args.getSize("--size", width, height);
    const int samples = std::clamp(args.getInt("--samples", 512), 2, 4096);
    Scene scene = loadScene(args.get("--scene", "basic"), defaultAssetsDir());
    const Camera* named = args.has("--camera") ? scene.findCamera(args.get("--camera")) : &scene.cameras.front();
    if (!named) throw ArgError("scene '" + scene.name + "' has no camera '" + args.get("--camera") + "'");
    std::vector<std::string> pixel =
        split(args.get("--pixel", std::to_string(width / 2) + "," + std::to_string(height / 2)), ',');
    std::vector<std::string> range = split(args.get("--range", "0,1"), ',');
    if (pixel.size() != 2 || range.size() != 2) throw ArgError("--pixel X,Y and --range LO,HI take two numbers");
    const int px = std::clamp(std::stoi(pixel[0]), 0, width - 1), py = std::clamp(std::stoi(pixel[1]), 0, height - 1);
    const float lo = std::stof(range[0]), hi = std::stof(range[1]);
    if (!(hi > lo)) throw ArgError("--range LO,HI needs LO < HI");

    HeadlessContext context;
    ShaderLibrary shaders(defaultShaderDir());
    VisibilityPlotRequest request{.techniques = split(args.get("--techniques", "vsm"), ','),
                                  .overrides = args.all("--set"),
                                  .width = width,
                                  .height = height,
                                  .pixel = {px, py},
                                  .samples = samples,
                                  .lo = lo,
                                  .hi = hi};
    const Plot plot = visibilityPlot(shaders, scene, *named, request);
    for (const auto& e : shaders.errors()) std::cerr << e;
    if (!shaders.errors().empty()) return 3;
    writePlotSvg(plot, args.get("--out"));
    std::cout << "plot: " << plot.title << "\n";
    return 0;
  } catch (const ArgError& e) {
    std::cerr << "plot: " << e.what() << "\n" << kPlotUsage;
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "plot: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace sl
