// `shadowlab render`: N frames headless, the last one (or a debug view) to PNG, stats to JSON.
#include "cli/args.h"
#include "cli/commands.h"
#include "gl/gl_util.h"
#include "gl/headless_context.h"
#include "render/renderer.h"
#include "technique.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>

namespace sl {

static const char* kRenderUsage =
    "usage: shadowlab render --scene S --technique T [--set key=value]... [--camera NAME | --path NAME]\n"
    "                        [--size WxH] [--frames N] [--view NAME] --out F.png [--stats F.json]\n";

static Camera pickCamera(const Scene& scene, const std::string& name) {
  if (name.empty()) return scene.cameras.front();
  if (const Camera* c = scene.findCamera(name)) return *c;
  std::string names;
  for (const auto& c : scene.cameras) names += (names.empty() ? "" : ", ") + c.name;
  throw ArgError("scene '" + scene.name + "' has no camera '" + name + "' (cameras: " + names + ")");
}

int runRenderCommand(int argc, char** argv) {
  for (int i = 2; i < argc; ++i)
    if (std::string(argv[i]) == "--help") {
      std::cout << kRenderUsage;
      return 0;
    }
  try {
    Args args(argc, argv, 2,
              {"--scene", "--technique", "--set", "--camera", "--path", "--size", "--frames", "--view", "--out",
               "--stats", "--shaders", "--time"});
    if (!args.has("--out")) throw ArgError("--out F.png is required");
    int width = 640, height = 360;
    args.getSize("--size", width, height);
    int frames = std::max(1, args.getInt("--frames", 1));
    Scene scene = loadScene(args.get("--scene", "basic"), defaultAssetsDir());
    Technique technique = makeTechnique(args.get("--technique", "standard"), args.all("--set"));
    Camera camera = pickCamera(scene, args.get("--camera"));
    const CameraPath* path = nullptr;
    if (args.has("--path")) {
      path = scene.findPath(args.get("--path"));
      if (!path) throw ArgError("scene '" + scene.name + "' has no camera path '" + args.get("--path") + "'");
    }

    HeadlessContext context;
    enableGlDebugOutput(true);
    ShaderLibrary shaders(args.get("--shaders", defaultShaderDir()));
    Renderer renderer(shaders);
    renderer.setScene(scene);
    Viewport viewport(technique);
    std::string view = args.get("--view");
    if (!view.empty()) {
      auto avail = viewport.availableViews();
      if (std::find(avail.begin(), avail.end(), view) == avail.end()) {
        std::string names;
        for (const auto& v : avail) names += (names.empty() ? "" : ", ") + v;
        throw ArgError("unknown view '" + view + "' (views: " + names + ")");
      }
      viewport.shownViews = {view};
    }

    std::vector<double> frameMs;
    double startTime = std::stod(args.get("--time", "0"));
    for (int f = 0; f < frames; ++f) {
      FrameInput in;
      in.time = startTime + f / 30.0;
      in.camera = path ? path->sample(static_cast<float>(f / 30.0), camera) : camera;
      in.width = width;
      in.height = height;
      renderer.render(in, {&viewport});
      frameMs.push_back(renderer.stats().frameMs);
    }
    auto errors = shaders.errors();
    for (const auto& e : errors) std::cerr << e;

    const Texture2D* out = view.empty() ? viewport.colorTexture() : viewport.viewTexture(view);
    writePng(args.get("--out"), width, height, out->readRgba8());
    std::vector<float> vis = viewport.visibilityTexture()->readFloats(2);
    long long nonfinite = 0;
    for (size_t i = 0; i < vis.size(); i += 2) nonfinite += std::isfinite(vis[i]) ? 0 : 1;

    if (args.has("--stats")) {
      nlohmann::json j;
      j["technique"] = technique.presetId;
      j["composition"] = {{"layout", technique.layout->id()},
                          {"representation", technique.representation->id()},
                          {"accumulation", technique.accumulation->id()}};
      for (const auto& d : technique.params.decls()) j["params"][d.key] = formatValue(d, technique.params.get(d.key));
      j["scene"] = scene.name;
      j["size"] = {width, height};
      j["frames"] = frames;
      j["passes"] = nlohmann::json::array();
      for (const auto& p : renderer.stats().passes) j["passes"].push_back(p.name);
      j["pass_ms"] = nlohmann::json::object();
      for (const auto& p : renderer.stats().passes) j["pass_ms"][p.name] = p.ms;
      std::vector<double> sorted = frameMs;
      std::sort(sorted.begin(), sorted.end());
      j["ms_per_frame"] = sorted[sorted.size() / 2];
      j["timer"] = renderer.stats().timer;
      j["renderer"] = glRendererName();
      j["nonfinite_pixels"] = nonfinite;
      // What each part says about the last frame (the irregular z-buffer's list overflow, the deep map's fragment-list
      // overflow, a hard test in an area-light scene ignoring the radius).
      j["status"] = {{"layout", viewport.layout->status()},
                     {"representation", viewport.representation->status()},
                     {"accumulation", viewport.accumulation->status()}};
      j["shadow_texels"] = viewport.shadowTexels();
      j["shader_errors"] = errors;
      j["gl_errors"] = glDebugErrorCount();
      std::ofstream f(args.get("--stats"));
      if (!f) throw std::runtime_error(args.get("--stats") + ": cannot write stats");
      f << j.dump(2) << "\n";
    }
    if (!errors.empty()) return 3;
    if (nonfinite > 0) {
      std::cerr << "render: " << nonfinite << " non-finite visibility pixels\n";
      return 4;
    }
    return 0;
  } catch (const ArgError& e) {
    std::cerr << "render: " << e.what() << "\n" << kRenderUsage;
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "render: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace sl
