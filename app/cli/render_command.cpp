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

// Shows `view` instead of the colour image (none: the colour image); an unknown name is an
// argument error listing the views the technique offers.
void showView(Viewport& viewport, const std::string& view) {
  if (view.empty()) return;
  auto avail = viewport.availableViews();
  if (std::find(avail.begin(), avail.end(), view) == avail.end()) {
    std::string names;
    for (const auto& v : avail) names += (names.empty() ? "" : ", ") + v;
    throw ArgError("unknown view '" + view + "' (views: " + names + ")");
  }
  viewport.shownViews = {view};
}

// What one render run was, for its --stats file.
struct RenderRun {
  const Technique* technique;
  const Scene* scene;
  const Viewport* viewport;
  const Renderer* renderer;
  int width, height, frames;
  long long nonfinite;
};

void writeRenderStats(const std::string& path, const RenderRun& run, const std::vector<double>& frameMs,
                      const std::vector<std::string>& errors) {
  nlohmann::json j;
  j["technique"] = run.technique->presetId;
  j["composition"] = {{"layout", run.technique->layout->id()},
                      {"representation", run.technique->representation->id()},
                      {"accumulation", run.technique->accumulation->id()}};
  for (const auto& d : run.technique->params.decls())
    j["params"][d.key] = formatValue(d, run.technique->params.get(d.key));
  j["scene"] = run.scene->name;
  j["size"] = {run.width, run.height};
  j["frames"] = run.frames;
  j["passes"] = nlohmann::json::array();
  for (const auto& p : run.renderer->stats().passes) j["passes"].push_back(p.name);
  j["pass_ms"] = nlohmann::json::object();
  for (const auto& p : run.renderer->stats().passes) j["pass_ms"][p.name] = p.ms;
  std::vector<double> sorted = frameMs;
  std::sort(sorted.begin(), sorted.end());
  j["ms_per_frame"] = sorted[sorted.size() / 2];
  j["timer"] = run.renderer->stats().timer;
  j["renderer"] = glRendererName();
  j["nonfinite_pixels"] = run.nonfinite;
  // What each part says about the last frame (the irregular z-buffer's list overflow, the deep map's fragment-list
  // overflow, a hard test in an area-light scene ignoring the radius).
  j["status"] = {{"layout", run.viewport->layout->status()},
                 {"representation", run.viewport->representation->status()},
                 {"accumulation", run.viewport->accumulation->status()},
                 {"viewport", run.viewport->status()}};  // the parts' joined, and several lights'
  j["shadow_texels"] = run.viewport->shadowTexels();
  j["shader_errors"] = errors;
  j["gl_errors"] = glDebugErrorCount();
  std::ofstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot write stats");
  f << j.dump(2) << "\n";
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
    const std::string view = args.get("--view");
    showView(viewport, view);

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
      const RenderRun run{&technique, &scene, &viewport, &renderer, width, height, frames, nonfinite};
      writeRenderStats(args.get("--stats"), run, frameMs, errors);
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
