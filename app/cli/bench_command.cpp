// `shadowlab bench`: techniques x sweeps, timed and compared with the ray-traced reference.
#include "bench/bench.h"
#include "cli/args.h"
#include "cli/commands.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace sl {

static const char* kBenchUsage =
    "usage: shadowlab bench --scene S --techniques a,b,c [--set key=value]... [--sweep key=v1,v2,...]...\n"
    "                       [--camera NAME | --path NAME] [--frames N] [--warmup N] [--approach N] [--size WxH]\n"
    "                       [--samples N] [--time T] [--no-cache] --json F.json [--report DIR]\n"
    "  One entry per technique x sweep point (sweeps multiply), each with its own viewport; the\n"
    "  entries are rendered in turn at each frame (A B A B ...) and ms_ratio is each entry's frame\n"
    "  time over the first entry's at the same frame (median, p25, p75): it holds from run to run.\n"
    "  --set applies to every technique that has the key (an error if none has it).\n"
    "  --frames N measured frames after --warmup frames (default 10 and 3). With --camera the\n"
    "  camera stands still and `convergence` is the error per frame against one reference;\n"
    "  with --path the camera moves at 30 fps and `flicker` compares temporal change with the\n"
    "  reference traced per frame, and `flicker.world` is the mean change at fixed world points\n"
    "  (the first frame's view shaded with maps fitted to each frame's camera: the truth is still).\n"
    "  References are cached (see `shadowlab reference`).\n"
    "  --approach N renders N frames of coherent motion before the measured frames, so accumulating\n"
    "  techniques start with a filled history (default 0: empty history): with --camera a rotation\n"
    "  into the view, with --path the N path frames before --time (the path clamps at its start).\n";

int runBenchCommand(int argc, char** argv) {
  try {
    Args args(argc, argv, 2,
              {"--scene", "--techniques", "--set", "--sweep", "--camera", "--path", "--frames", "--warmup",
               "--approach", "--size", "--samples", "--time", "--json", "--report", "--shaders"},
              {"--no-cache", "--help"});
    if (args.has("--help")) {
      std::cout << kBenchUsage;
      return 0;
    }
    BenchOptions o;
    o.scene = args.get("--scene", "basic");
    std::istringstream list(args.get("--techniques"));
    for (std::string t; std::getline(list, t, ',');)
      if (!t.empty()) o.techniques.push_back(t);
    o.sets = args.all("--set");
    o.sweeps = args.all("--sweep");
    if (args.has("--camera") && args.has("--path")) throw ArgError("give --camera or --path, not both");
    o.camera = args.get("--camera");
    o.path = args.get("--path");
    o.frames = args.getInt("--frames", o.frames);
    o.warmup = args.getInt("--warmup", o.warmup);
    o.approach = args.getInt("--approach", o.approach);
    args.getSize("--size", o.width, o.height);
    o.samples = args.getInt("--samples", o.samples);
    if (o.samples < 1) throw ArgError("--samples must be at least 1");
    o.time = std::stod(args.get("--time", "0"));
    o.useCache = !args.has("--no-cache");
    o.shaderDir = args.get("--shaders");
    if (!args.has("--json") && !args.has("--report")) throw ArgError("--json F.json (or --report DIR) is required");
    for (int i = 0; i < argc; ++i) {
      std::string a = argv[i];
      if (i == 0) a = "shadowlab";
      if (a.find_first_of(" \t'\"") != std::string::npos) a = "'" + a + "'";
      o.commandLine += (i ? " " : "") + a;
    }
    planBench(o);  // every argument error before the (slow) run

    BenchResult r = runBench(o, std::cerr);
    if (args.has("--json")) {
      std::filesystem::path jp(args.get("--json"));
      if (jp.has_parent_path()) std::filesystem::create_directories(jp.parent_path());
      std::ofstream f(jp);
      if (!f) throw std::runtime_error(args.get("--json") + ": cannot write");
      f << benchToJson(r).dump(2) << "\n";
    }
    if (args.has("--report")) {
      writeBenchReport(r, args.get("--report"));
      std::cerr << "bench: report in " << args.get("--report") << "/index.html\n";
    }
    if (!r.shaderErrors.empty()) {
      std::cerr << "bench: shader errors (see above); results written but not trustworthy\n";
      return 3;
    }
    long long nonfinite = 0;
    for (const auto& e : r.entries) nonfinite += e.nonfinite;
    if (nonfinite > 0) {
      std::cerr << "bench: " << nonfinite << " non-finite visibility pixels (see nonfinite_pixels)\n";
      return 4;
    }
    return 0;
  } catch (const ArgError& e) {
    std::cerr << "bench: " << e.what() << "\n" << kBenchUsage;
    return 1;
  } catch (const ParamError& e) {
    std::cerr << "bench: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "bench: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace sl
