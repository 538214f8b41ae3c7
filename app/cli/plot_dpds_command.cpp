// `shadowlab plot dpds`: the survey's perspective-aliasing curves (techniques/layouts/dpds.h) as
// an SVG, headless and without a GPU (the layouts' light spaces are computed on the CPU).
#include "cli/args.h"
#include "cli/commands.h"
#include "gl/shader_library.h"
#include "plot/dpds.h"

#include <iostream>
#include <sstream>

namespace sl {

static const char* kDpdsUsage =
    "usage: shadowlab plot dpds --scene S [--camera NAME] [--size WxH] [--techniques a,b:key=v;key=v,...]\n"
    "                           --out F.svg\n"
    "  Texel size over pixel size along the view direction for receivers on the camera's centre\n"
    "  ray, per technique (default: uniform, standard, psm, lispsm, lispsm with n = z_n, logpsm,\n"
    "  cascaded),\n"
    "  and the ideal logarithmic curve for the first technique's texels per side. Overrides of one\n"
    "  technique follow a ':' and are separated by ';'.\n";

int runPlotDpdsCommand(int argc, char** argv) {
  try {
    if (argc < 3 || std::string(argv[2]) != "dpds") {
      std::cout << kDpdsUsage;
      return argc >= 3 && (std::string(argv[2]) == "--help") ? 0 : 1;
    }
    Args args(argc, argv, 3, {"--scene", "--camera", "--size", "--techniques", "--out"}, {"--help"});
    if (args.has("--help")) {
      std::cout << kDpdsUsage;
      return 0;
    }
    if (!args.has("--out")) throw ArgError("--out F.svg is required");
    int width = 1280, height = 720;
    args.getSize("--size", width, height);
    const Scene scene = loadScene(args.get("--scene", "columns"), defaultAssetsDir());
    const Camera* cam = args.has("--camera") ? scene.findCamera(args.get("--camera")) : &scene.cameras.front();
    if (!cam) throw ArgError("no camera '" + args.get("--camera") + "' in the scene");
    std::vector<std::string> techniques;
    std::stringstream list(args.get("--techniques", "uniform,standard,psm,lispsm,lispsm:lispsm.n=z_n,logpsm,cascaded"));
    for (std::string t; std::getline(list, t, ',');) {
      for (char& c : t)
        if (c == ';') c = ',';  // dpdsCurves separates one technique's overrides by ','
      techniques.push_back(t);
    }
    const auto curves = dpdsCurves(scene, *cam, width, height, techniques);
    writePlotSvg(dpdsPlot(curves, "dp/ds on '" + scene.name + "', camera '" + cam->name + "'"), args.get("--out"));
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "plot: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace sl
