// `shadowlab plot`: visibility against receiver depth at the shadow-map texel under one screen
// pixel, for pre-filtered techniques, as an SVG: the true lit fraction of the filter box (the
// step, softened by what the box holds) and each representation's reconstruction, so ringing
// (Fourier) and leaking (Chebyshev) show at a glance.
#include "cli/args.h"
#include "cli/commands.h"
#include "gl/gl_util.h"
#include "gl/headless_context.h"
#include "prefiltered/visibility_curve.h"
#include "render/renderer.h"

#include <fstream>
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

struct Curve {
  std::string label, color;
  std::vector<float> values;
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, sep);)
    if (!item.empty()) out.push_back(item);
  return out;
}

void writeSvg(const std::string& path, const std::vector<Curve>& curves, float lo, float hi, float receiver,
              const std::string& title) {
  const float w = 720, h = 400, left = 50, right = 150, top = 30, bottom = 40;
  auto X = [&](float d) { return left + (d - lo) / (hi - lo) * (w - left - right); };
  auto Y = [&](float v) { return top + (1.0f - v) * (h - top - bottom); };
  std::ofstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot write");
  f << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  f << "<text x=\"" << left << "\" y=\"18\">" << title << "</text>\n";
  for (float v : {0.0f, 0.5f, 1.0f})
    f << "<line x1=\"" << left << "\" x2=\"" << w - right << "\" y1=\"" << Y(v) << "\" y2=\"" << Y(v)
      << "\" stroke=\"#ddd\"/><text x=\"" << left - 30 << "\" y=\"" << Y(v) + 4 << "\">" << v << "</text>\n";
  f << "<line x1=\"" << X(receiver) << "\" x2=\"" << X(receiver) << "\" y1=\"" << top << "\" y2=\"" << h - bottom
    << "\" stroke=\"#999\" stroke-dasharray=\"4 3\"/>\n";
  f << "<text x=\"" << left << "\" y=\"" << h - 10 << "\">receiver depth " << lo << " .. " << hi
    << " (dashed: this pixel's)</text>\n";
  for (size_t c = 0; c < curves.size(); ++c) {
    const Curve& cv = curves[c];
    f << "<polyline fill=\"none\" stroke=\"" << cv.color << "\" stroke-width=\"" << (c == 0 ? 2.5 : 1.5)
      << "\" points=\"";
    const size_t n = cv.values.size();
    for (size_t i = 0; i < n; ++i) {
      const float d = static_cast<float>(i) / static_cast<float>(std::max<size_t>(n - 1, 1));
      if (d < lo || d > hi) continue;
      f << X(d) << "," << Y(std::clamp(cv.values[i], -0.2f, 1.2f)) << " ";
    }
    f << "\"/>\n<text x=\"" << w - right + 10 << "\" y=\"" << top + 16 * c + 10 << "\" fill=\"" << cv.color << "\">"
      << cv.label << "</text>\n";
  }
  f << "</svg>\n";
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
    Renderer renderer(shaders);
    renderer.setScene(scene);
    static const char* colors[] = {"#d62728", "#1f77b4", "#2ca02c", "#ff7f0e",
                                   "#9467bd", "#8c564b", "#e377c2", "#17becf"};
    std::vector<Curve> curves;
    glm::vec3 uvLayer(0.5f, 0.5f, 0.0f);
    float receiver = 0.5f;
    for (const std::string& id : split(args.get("--techniques", "vsm"), ',')) {
      Viewport vp(makeTechnique(id, args.all("--set")));
      FrameInput in;
      in.camera = *named;
      in.width = width;
      in.height = height;
      renderer.render(in, {&vp});
      const auto* state = dynamic_cast<const MomentMapState*>(vp.representation.get());
      if (!state) throw ArgError("technique '" + id + "' is not pre-filtered (its representation stores no moments)");
      if (curves.empty()) {
        const std::vector<float> pos = renderer.gPosition().readFloats(4);
        const size_t i = (static_cast<size_t>(py) * width + px) * 4;
        if (pos[i + 3] < 0.5f) throw ArgError("pixel " + pixel[0] + "," + pixel[1] + " shows no surface");
        if (!mapPointOf(glm::vec3(pos[i], pos[i + 1], pos[i + 2]), vp.lightSpace.primary(), uvLayer, receiver))
          throw ArgError("pixel " + pixel[0] + "," + pixel[1] + " is behind the light's view");
        curves.push_back({"true (box of " + std::to_string(vp.technique.params.i("filter.width")) + " texels)", "black",
                          trueCurve(*state->depthTexture(), uvLayer, vp.technique.params.i("filter.width"), samples)});
      }
      curves.push_back(
          {id, colors[(curves.size() - 1) % 8], reconstructedCurve(shaders, vp.technique, *state, uvLayer, samples)});
    }
    for (const auto& e : shaders.errors()) std::cerr << e;
    if (!shaders.errors().empty()) return 3;
    std::ostringstream title;
    title << scene.name << ", pixel " << px << "," << py << ": visibility vs receiver depth at map uv " << uvLayer.x
          << ", " << uvLayer.y;
    writeSvg(args.get("--out"), curves, lo, hi, receiver, title.str());
    std::cout << "plot: receiver depth " << receiver << " at map uv " << uvLayer.x << ", " << uvLayer.y << "\n";
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
