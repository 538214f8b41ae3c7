// `shadowlab reference`: the ray-traced shadow visibility of one frame as a grey PNG, cached.
#include "bench/reference_cache.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "gl/headless_context.h"

#include <iostream>

namespace sl {

static const char* kReferenceUsage =
    "usage: shadowlab reference --scene S [--camera NAME] [--size WxH] [--samples N] [--time T]\n"
    "                           [--no-cache] --out F.png\n"
    "  Ray-traces the shadow visibility of the rasterized G-buffer (white = lit). Results are\n"
    "  cached in $XDG_CACHE_HOME/shadowlab (default ~/.cache/shadowlab).\n";

int runReferenceCommand(int argc, char** argv) {
  try {
    Args args(argc, argv, 2, {"--scene", "--camera", "--size", "--samples", "--time", "--out", "--shaders"},
              {"--no-cache", "--help"});
    if (args.has("--help")) {
      std::cout << kReferenceUsage;
      return 0;
    }
    if (!args.has("--out")) throw ArgError("--out F.png is required");
    int width = 640, height = 360;
    args.getSize("--size", width, height);
    Scene scene = loadScene(args.get("--scene", "basic"), defaultAssetsDir());
    FrameInput in;
    in.width = width;
    in.height = height;
    in.time = std::stod(args.get("--time", "0"));
    const std::string camName = args.get("--camera");
    if (camName.empty()) {
      in.camera = scene.cameras.front();
    } else if (const Camera* c = scene.findCamera(camName)) {
      in.camera = *c;
    } else {
      std::string names;
      for (const auto& c : scene.cameras) names += (names.empty() ? "" : ", ") + c.name;
      throw ArgError("scene '" + scene.name + "' has no camera '" + camName + "' (cameras: " + names + ")");
    }
    ReferenceSettings settings;
    settings.samples = args.getInt("--samples", 64);
    if (settings.samples < 1) throw ArgError("--samples must be at least 1");
    settings.useCache = !args.has("--no-cache");

    HeadlessContext context;
    ShaderLibrary shaders(args.get("--shaders", defaultShaderDir()));
    Renderer renderer(shaders);
    renderer.setScene(scene);
    ReferenceCache cache(scene, settings);
    ReferenceImage ref = cache.forFrame(renderer, in);
    if (ref.cached)
      std::cout << "reference: cached (" << ref.cacheFile << ")\n";
    else
      std::cout << "reference: traced in " << static_cast<long long>(ref.traceMs + 0.5) << " ms (" << width << "x"
                << height << ", " << (scene.light.radius > 0 ? settings.samples : 1) << " rays/pixel)"
                << (settings.useCache ? ", stored in " + ref.cacheFile : std::string()) << "\n";
    writePng(args.get("--out"), width, height, visibilityToRgba(ref.visibility));
    return 0;
  } catch (const ArgError& e) {
    std::cerr << "reference: " << e.what() << "\n" << kReferenceUsage;
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "reference: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace sl
