// `shadowlab figure`: renders tour steps headless as figures (tour/figure.h), one PNG per step,
// plus an SVG beside it for a step with a plot (the plot drawn under the panels, tour/step_plot.h).
#include "cli/args.h"
#include "tour/tour_claims.h"
#include "cli/commands.h"
#include "gl/gl_util.h"
#include "gl/headless_context.h"
#include "gl/shader_library.h"
#include "tour/figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace sl {
namespace {

namespace fs = std::filesystem;

const char* kFigureUsage =
    "usage: shadowlab figure --tour T.json (--step N --out F.png | --all --out DIR) [--size WxH]\n"
    "                        [--aspect W:H] [--check]\n"
    "  renders tour steps headless for slides: every viewport and its debug views (for each frame\n"
    "  count of the step) in a grid whose figure comes closest to --aspect (default 16:9), title and\n"
    "  caption burnt in, text at least 1/40 of the figure's height. N counts from 1; --size is one\n"
    "  panel (default 480x270). --all writes DIR/step-01.png ...; a step with a plot draws it under\n"
    "  the panels at full width and also writes it as F.svg. --check also checks each step's claims\n"
    "  (docs/tour-format.md) against the ray-traced reference at the panel size, prints them, and\n"
    "  exits with 5 when one does not hold.\n";

// "16:9" or "1.78": a finite width / height ratio between 1/8 and 8.
float parseAspect(const std::string& text) {
  float w = 0, h = 1;
  char extra = 0;
  const bool ok = text.find(':') != std::string::npos ? std::sscanf(text.c_str(), "%f:%f%c", &w, &h, &extra) == 2
                                                      : std::sscanf(text.c_str(), "%f%c", &w, &extra) == 1;
  const float a = ok && h > 0 ? w / h : 0.0f;
  if (!std::isfinite(a) || a < 0.125f || a > 8.0f)
    throw ArgError("--aspect " + text + ": expected W:H (e.g. 16:9) or a ratio between 0.125 and 8");
  return a;
}

}  // namespace

int runFigureCommand(int argc, char** argv) {
  for (int i = 2; i < argc; ++i)
    if (std::string(argv[i]) == "--help") {
      std::cout << kFigureUsage;
      return 0;
    }
  try {
    Args args(argc, argv, 2, {"--tour", "--step", "--out", "--size", "--aspect", "--shaders"}, {"--all", "--check"});
    if (!args.has("--tour")) throw ArgError("--tour T.json is required");
    if (!args.has("--out")) throw ArgError("--out is required");
    if (args.has("--all") == args.has("--step")) throw ArgError("give either --step N or --all");
    FigureOptions options;
    args.getSize("--size", options.panelWidth, options.panelHeight);
    if (args.has("--aspect")) options.aspect = parseAspect(args.get("--aspect"));
    const Tour tour = loadTour(args.get("--tour"));
    std::vector<std::pair<size_t, std::string>> jobs;  // step, PNG path
    if (args.has("--all")) {
      fs::create_directories(args.get("--out"));
      for (size_t i = 0; i < tour.steps.size(); ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "step-%02zu.png", i + 1);
        jobs.emplace_back(i, (fs::path(args.get("--out")) / name).string());
      }
    } else {
      const int n = args.getInt("--step", 0);
      if (n < 1 || n > static_cast<int>(tour.steps.size()))
        throw ArgError("--step " + args.get("--step") + ": " + tour.file + " has steps 1 to " +
                       std::to_string(tour.steps.size()));
      jobs.emplace_back(size_t(n - 1), args.get("--out"));
    }

    long long nonfinite = 0;
    int claimsFailed = 0;
    std::vector<std::string> errors;
    {
      HeadlessContext context;
      enableGlDebugOutput(true);
      ShaderLibrary shaders(args.get("--shaders", defaultShaderDir()));
      for (const auto& [step, png] : jobs) {
        const FigureResult r = renderTourFigure(tour, step, shaders, options);
        writePng(png, r.image.width, r.image.height, [&] {
          // writePng takes GL's bottom-up rows.
          std::vector<unsigned char> flipped(r.image.pixels.size());
          const size_t row = size_t(r.image.width) * 4;
          for (int y = 0; y < r.image.height; ++y)
            std::copy_n(&r.image.pixels[size_t(r.image.height - 1 - y) * row], row, &flipped[size_t(y) * row]);
          return flipped;
        }());
        nonfinite += r.nonfinitePixels;
        std::cout << "figure: " << png << " (" << describeStep(tour, step) << ", " << r.panels << " panels"
                  << (tour.steps[step].built() ? "" : ", not built yet") << ")\n";
        if (!r.plot.empty()) writePlotSvg(r.plot, fs::path(png).replace_extension(".svg").string());
        if (args.has("--check"))
          for (const ClaimCheck& c :
               checkStepClaims(tour, step, shaders, options.panelWidth, options.panelHeight, "")) {
            std::cout << "claim: " << describeStep(tour, step) << ": " << c.text << "\n";
            claimsFailed += c.holds ? 0 : 1;
          }
      }
      errors = shaders.errors();
    }
    for (const auto& e : errors) std::cerr << e;
    if (!errors.empty()) return 3;
    if (nonfinite > 0) {
      std::cerr << "figure: " << nonfinite << " non-finite visibility pixels\n";
      return 4;
    }
    if (claimsFailed > 0) {
      std::cerr << "figure: " << claimsFailed << " claim(s) do not hold\n";
      return 5;
    }
    return 0;
  } catch (const ArgError& e) {
    std::cerr << "figure: " << e.what() << "\n" << kFigureUsage;
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "figure: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace sl
