// `shadowlab bench` and `shadowlab reference`: the JSON has every documented field, the
// instrument sees shadow-map resolution, the reference cache is exact, bad keys fail clearly.
// Runs the built program (SHADOWLAB_BINARY) headless on llvmpipe at small sizes.
#include "bench/bench.h"
#include "bench/reference_cache.h"
#include "gl/headless_context.h"
#include "sanitizer_report.h"
#include "technique.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace sl {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test, also used as XDG_CACHE_HOME so tests never share a cache.
struct BenchTempDir {
  fs::path path;
  BenchTempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path = fs::temp_directory_path() /
           ("shadowlab-bench-test-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
    ::setenv("XDG_CACHE_HOME", (path / "cache").c_str(), 1);
  }
  ~BenchTempDir() { fs::remove_all(path); }
};

std::string readFile(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

struct CommandResult {
  int code = -1;
  std::string out;  // stdout + stderr
};

CommandResult runCommand(const std::string& args, const fs::path& dir) {
  const fs::path log = dir / "log.txt";
  std::string cmd = std::string("'") + SHADOWLAB_BINARY + "' " + args + " > '" + log.string() + "' 2>&1";
  int status = std::system(cmd.c_str());
  CommandResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readFile(log);
  test::expectNoSanitizerReport(r.out, args);
  return r;
}

nlohmann::json readJson(const fs::path& p) { return nlohmann::json::parse(readFile(p)); }

TEST(Bench, JsonHasEveryFieldAndReport) {
  BenchTempDir t;
  const fs::path json = t.path / "b.json", report = t.path / "report";
  CommandResult r = runCommand(
      "bench --scene basic --techniques standard,pcf --sweep shadowmap.size=256,512 --size 160x90 "
      "--frames 3 --warmup 1 --json '" +
          json.string() + "' --report '" + report.string() + "'",
      t.path);
  ASSERT_EQ(r.code, 0) << r.out;
  nlohmann::json j = readJson(json);
  for (const char* k : {"scene", "size", "camera", "renderer", "timer", "machine", "date", "command", "entries"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(j["scene"], "basic");
  EXPECT_EQ(j["size"], nlohmann::json({160, 90}));
  EXPECT_EQ(j["camera"], "default");
  EXPECT_GE(j["machine"]["cores"].get<int>(), 1);
  EXPECT_NE(j["command"].get<std::string>().find("--techniques standard,pcf"), std::string::npos);
  ASSERT_EQ(j["entries"].size(), 4u);  // 2 techniques x 2 sweep points
  for (const auto& e : j["entries"]) {
    for (const char* k : {"technique", "params", "frames", "timer", "ms_per_frame", "ms_ratio", "passes", "error",
                          "convergence", "flicker", "nonfinite_pixels"})
      EXPECT_TRUE(e.contains(k)) << k;
    EXPECT_EQ(e["frames"], 3);
    EXPECT_TRUE(e["params"].contains("shadowmap.size"));
    EXPECT_TRUE(e["params"].contains("bias.mode"));  // all resolved values, not only the swept one
    EXPECT_GT(e["ms_per_frame"]["median"].get<double>(), 0.0);
    EXPECT_GE(e["ms_per_frame"]["p95"].get<double>(), e["ms_per_frame"]["median"].get<double>());
    ASSERT_FALSE(e["passes"].empty());
    for (const auto& p : e["passes"]) {
      EXPECT_TRUE(p["name"].is_string());
      EXPECT_GE(p["ms"].get<double>(), 0.0);
    }
    const auto& ratio = e["ms_ratio"];
    EXPECT_GT(ratio["median"].get<double>(), 0.0);
    EXPECT_LE(ratio["p25"].get<double>(), ratio["median"].get<double>());
    EXPECT_GE(ratio["p75"].get<double>(), ratio["median"].get<double>());
    for (const char* k : {"wrong_pixel_pct", "false_shadow_pct", "false_light_pct", "image_wrong_pct", "rmse"}) {
      ASSERT_TRUE(e["error"].contains(k)) << k;
      EXPECT_TRUE(std::isfinite(e["error"][k].get<double>())) << k;
    }
    EXPECT_EQ(e["convergence"].size(), 3u);
    EXPECT_DOUBLE_EQ(e["convergence"].back().get<double>(), e["error"]["wrong_pixel_pct"].get<double>());
    EXPECT_TRUE(e["flicker"].is_null());  // only with --path
    EXPECT_EQ(e["nonfinite_pixels"], 0);
  }
  // Image-wrong pixels are visibility-wrong ones the shading shows: never more than those here
  // (the colour's slope in visibility is below 1, up to rounding), but some.
  for (const auto& e : j["entries"])
    EXPECT_LE(e["error"]["image_wrong_pct"].get<double>(), e["error"]["wrong_pixel_pct"].get<double>() + 0.1);
  EXPECT_GT(j["entries"][2]["error"]["image_wrong_pct"].get<double>(), 0.0);  // pcf 256: a penumbra
  EXPECT_EQ(j["timing_order"], "interleaved");
  EXPECT_EQ(j["ms_ratio_baseline"], j["entries"][0]["label"]);
  EXPECT_DOUBLE_EQ(j["entries"][0]["ms_ratio"]["median"].get<double>(), 1.0);  // the baseline itself
  EXPECT_EQ(j["entries"][0]["params"]["shadowmap.size"], "256");
  EXPECT_EQ(j["entries"][1]["params"]["shadowmap.size"], "512");
  EXPECT_EQ(j["entries"][2]["technique"], "pcf");

  const std::string html = readFile(report / "index.html");
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("Pareto"), std::string::npos);
  EXPECT_EQ(html.find("http"), std::string::npos) << "the report must not load anything from the network";
  EXPECT_TRUE(fs::exists(report / "results.csv"));
  EXPECT_TRUE(fs::exists(report / "reference.png"));
  EXPECT_TRUE(fs::exists(report / "01-standard-256-error.png"));
  EXPECT_TRUE(fs::exists(report / "04-pcf-512-visibility.png"));
}

TEST(Bench, PathMeasuresFlicker) {
  BenchTempDir t;
  const fs::path json = t.path / "b.json";
  CommandResult r = runCommand(
      "bench --scene basic --techniques standard --path orbit --size 160x90 --frames 4 --warmup 0 "
      "--json '" +
          json.string() + "'",
      t.path);
  ASSERT_EQ(r.code, 0) << r.out;
  nlohmann::json j = readJson(json);
  EXPECT_EQ(j["path"], "orbit");
  ASSERT_EQ(j["entries"].size(), 1u);
  const auto& f = j["entries"][0]["flicker"];
  ASSERT_TRUE(f.is_object()) << f;
  EXPECT_GT(f["reference"].get<double>(), 0.0);  // the camera moves: the image changes
  // Per-pixel excess, clipped at 0: at least the difference of the means, never negative.
  EXPECT_GE(f["excess"].get<double>(), f["technique"].get<double>() - f["reference"].get<double>() - 1e-12);
  EXPECT_GE(f["excess"].get<double>(), 0.0);
  EXPECT_EQ(j["reference"]["traced"].get<int>() + j["reference"]["cached"].get<int>(), 4);
  // The per-frame references are cached: a second run traces nothing.
  r = runCommand("bench --scene basic --techniques standard --path orbit --size 160x90 --frames 4 --warmup 0 --json '" +
                     json.string() + "'",
                 t.path);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(readJson(json)["reference"]["cached"], 4);
}

// Entries are rendered in turn (A B A B ...) with one viewport each: an entry's images must be
// those it gives when benched alone, along a moving camera and after an approach (where the
// previous frame feeds reprojection and "camera moved").
TEST(Bench, RenderingInTurnDoesNotChangeAnEntrysImages) {
  BenchTempDir t;
  BenchOptions o;
  o.scene = "basic";
  o.path = "orbit";
  o.approach = 3;
  o.frames = 4;
  o.warmup = 1;
  o.width = 96;
  o.height = 54;
  std::ostringstream log;
  o.techniques = {"pixel-correct"};
  const BenchResult alone = runBench(o, log);
  o.techniques = {"standard"};
  const BenchResult standardAlone = runBench(o, log);
  o.techniques = {"standard", "pixel-correct", "pcf"};
  const BenchResult together = runBench(o, log);
  ASSERT_EQ(together.entries.size(), 3u);
  const BenchEntry& pc = together.entries[1];
  ASSERT_EQ(pc.technique, "pixel-correct");
  ASSERT_EQ(pc.lastVisibility.size(), 96u * 54u);
  EXPECT_EQ(pc.lastVisibility, alone.entries[0].lastVisibility);  // bit-identical
  EXPECT_EQ(pc.convergence, alone.entries[0].convergence);
  EXPECT_EQ(pc.flickerTechnique, alone.entries[0].flickerTechnique);
  EXPECT_EQ(together.entries[0].lastVisibility, standardAlone.entries[0].lastVisibility);
  EXPECT_EQ(pc.image.imageWrongPct, alone.entries[0].image.imageWrongPct);
  EXPECT_DOUBLE_EQ(together.entries[0].msRatio, 1.0);
  EXPECT_GT(pc.msRatio, 0.0);
}

TEST(Bench, SeesShadowMapResolution) {
  BenchTempDir t;
  const fs::path json = t.path / "b.json";
  CommandResult r = runCommand(
      "bench --scene basic --techniques standard --sweep shadowmap.size=256,4096 --size 320x180 "
      "--frames 1 --warmup 1 --json '" +
          json.string() + "'",
      t.path);
  ASSERT_EQ(r.code, 0) << r.out;
  nlohmann::json j = readJson(json);
  ASSERT_EQ(j["entries"].size(), 2u);
  const double low = j["entries"][0]["error"]["wrong_pixel_pct"];
  const double high = j["entries"][1]["error"]["wrong_pixel_pct"];
  EXPECT_LT(high, 1.0);
  EXPECT_GT(low, 3.0 * high) << "256: " << low << " %, 4096: " << high << " %";
  EXPECT_GT(low - high, 0.02);
}

// A scene of several lights: each other light's error against the reference traced toward it,
// and which ones the budget left unshadowed (the first light's stays `error`).
TEST(Bench, MeasuresEveryLightOfTheScene) {
  BenchTempDir t;
  BenchOptions o;
  o.scene = "street-lamps";
  o.techniques = {"cube"};
  o.sweeps = {"lights.shadowed=4,2"};
  o.sets = {"shadowmap.size=256"};
  o.frames = 1;
  o.warmup = 1;
  o.width = 96;
  o.height = 54;
  std::ostringstream log;
  const BenchResult r = runBench(o, log);
  ASSERT_EQ(r.entries.size(), 2u);
  for (const BenchEntry& e : r.entries) ASSERT_EQ(e.otherLights.size(), 3u) << e.label;
  for (const auto& l : r.entries[0].otherLights) {
    EXPECT_TRUE(l.shadowed);
    EXPECT_LE(l.error.wrongPixelPct, 5.0);
    EXPECT_GT(l.error.validPixels, 0);
  }
  EXPECT_TRUE(r.entries[1].otherLights[0].shadowed);
  EXPECT_FALSE(r.entries[1].otherLights[1].shadowed);
  EXPECT_FALSE(r.entries[1].otherLights[2].shadowed);
  // Two lamps lighting through casters: the colour is further from the truth.
  EXPECT_GT(r.entries[1].image.imageWrongPct, r.entries[0].image.imageWrongPct);
  const nlohmann::json j = benchToJson(r);
  EXPECT_EQ(j["entries"][1]["error"]["other_lights"].size(), 3u);
  EXPECT_EQ(j["entries"][1]["error"]["other_lights"][2]["shadowed"], false);
  EXPECT_EQ(j["entries"][0]["error"]["other_lights"][0]["light"], 2);
}

TEST(Bench, BadKeysFailClearly) {
  BenchTempDir t;
  const std::string base = "bench --scene basic --techniques standard,pcf --size 64x36 --frames 1 --json '" +
                           (t.path / "b.json").string() + "' ";
  CommandResult r = runCommand(base + "--sweep no.such.key=1,2", t.path);
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.out.find("no.such.key"), std::string::npos) << r.out;
  r = runCommand(base + "--set bogus=3", t.path);
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.out.find("bogus"), std::string::npos) << r.out;
  r = runCommand(base + "--sweep shadowmap.size=256,99999", t.path);  // out of range
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.out.find("shadowmap.size"), std::string::npos) << r.out;
  r = runCommand(base + "--sweep shadowmap.size", t.path);  // no values
  EXPECT_NE(r.code, 0);
  r = runCommand(
      std::string("bench --scene basic --techniques nosuchtechnique --json '") + (t.path / "b.json").string() + "'",
      t.path);
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.out.find("nosuchtechnique"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(t.path / "b.json"));
}

TEST(ReferenceCache, CommandCachesItsResult) {
  BenchTempDir t;
  const std::string args = "reference --scene basic --size 96x54 --out '";
  CommandResult a = runCommand(args + (t.path / "a.png").string() + "'", t.path);
  ASSERT_EQ(a.code, 0) << a.out;
  EXPECT_NE(a.out.find("traced in"), std::string::npos) << a.out;
  CommandResult b = runCommand(args + (t.path / "b.png").string() + "'", t.path);
  ASSERT_EQ(b.code, 0) << b.out;
  EXPECT_NE(b.out.find("reference: cached"), std::string::npos) << b.out;
  EXPECT_EQ(readFile(t.path / "a.png"), readFile(t.path / "b.png"));
  // Another camera is another key.
  CommandResult c = runCommand(
      "reference --scene basic --camera top --size 96x54 --out '" + (t.path / "c.png").string() + "'", t.path);
  ASSERT_EQ(c.code, 0) << c.out;
  EXPECT_NE(c.out.find("traced in"), std::string::npos) << c.out;
}

TEST(ReferenceCache, CacheReturnsIdenticalValuesInProcess) {
  BenchTempDir t;
  HeadlessContext context;
  ShaderLibrary shaders(defaultShaderDir());
  Renderer renderer(shaders);
  Scene scene = loadScene("basic", defaultAssetsDir());
  renderer.setScene(scene);
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 80;
  in.height = 45;
  ReferenceSettings s;
  s.cacheDir = (t.path / "refcache").string();
  ReferenceImage first = ReferenceCache(scene, s).forFrame(renderer, in);
  ReferenceImage second = ReferenceCache(scene, s).forFrame(renderer, in);
  EXPECT_FALSE(first.cached);
  EXPECT_TRUE(second.cached);
  EXPECT_EQ(first.key, second.key);
  ASSERT_EQ(first.visibility.size(), 80u * 45u);
  EXPECT_EQ(first.visibility, second.visibility);  // bit-identical floats
  EXPECT_EQ(first.valid, second.valid);
  long long lit = 0, covered = 0;
  for (size_t i = 0; i < first.valid.size(); ++i) {
    covered += first.valid[i];
    lit += first.visibility[i] > 0.5f;
  }
  EXPECT_GT(covered, 0);
  EXPECT_GT(lit, 0);
  EXPECT_LT(lit, covered);  // some shadow in view

  // A viewport compared with the reference of its own frame: the explorer's error panel path.
  Viewport vp(makeTechnique("standard", {"shadowmap.size=4096"}));
  renderer.render(in, {&vp});
  ErrorMetrics m = viewportErrorMetrics(vp, second);
  EXPECT_EQ(m.validPixels, covered);
  EXPECT_LT(m.wrongPixelPct, 5.0);
  EXPECT_EQ(viewportErrorImage(vp, second).size(), 80u * 45u * 4u);

  // A changed camera misses the cache.
  in.camera.position.x += 0.01f;
  ReferenceImage moved;
  EXPECT_FALSE(ReferenceCache(scene, s).lookup(in, moved));
}

// World-space flicker (the path's first view shaded with maps fitted to each frame's camera):
// a map that ignores the camera (`uniform`) must read exactly 0, an unsnapped focused map more,
// and snapped cascades at most 1/5 of unsnapped ones (issue 9's aim, which the screen-space
// metric cannot show: it gives `uniform`, whose map never changes, a nonzero excess too).
TEST(Bench, WorldFlickerIsZeroForAStillMapAndSeesSnapping) {
  BenchOptions o;
  o.scene = "basic";
  o.path = "orbit";
  o.frames = 8;
  o.warmup = 1;
  o.width = 96;
  o.height = 54;
  o.techniques = {"uniform", "standard", "cascaded"};
  o.sweeps = {"layout.snap=on,off"};
  std::ostringstream log;
  const BenchResult r = runBench(o, log);
  ASSERT_EQ(r.entries.size(), 6u);
  std::map<std::string, double> world;
  for (const auto& e : r.entries) {
    EXPECT_TRUE(e.hasFlicker) << e.label;
    world[e.label] = e.worldFlicker;
  }
  for (const auto& [label, w] : world) std::printf("world flicker %s: %.6f\n", label.c_str(), w);
  EXPECT_EQ(world["uniform layout.snap=on"], 0.0);
  EXPECT_EQ(world["uniform layout.snap=off"], 0.0);
  EXPECT_GT(world["standard layout.snap=off"], 1e-4);
  EXPECT_GT(world["cascaded layout.snap=off"], 1e-4);
  EXPECT_LE(world["cascaded layout.snap=on"], 0.2 * world["cascaded layout.snap=off"]);
}

}  // namespace
}  // namespace sl
