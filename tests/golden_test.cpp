// Every preset against images rendered before a change of the part interfaces (tests/goldens/),
// compared with tolerances as filament compares its Mesa goldens: a pixel fails when a channel
// differs by more than kChannelTolerance, and a test fails when more than kFailingFraction of the
// pixels fail or the mean difference exceeds kMeanTolerance.
// SHADOWLAB_UPDATE_GOLDENS=1 writes the images instead (then look at them before committing).
#include "gl_test_util.h"
#include "technique.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace sl {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 96, kHeight = 54;
constexpr int kFrames = 6;  // accumulations converge for a few frames; all presets run as many
constexpr int kChannelTolerance = 8;
constexpr double kFailingFraction = 0.005, kMeanTolerance = 1.0;

fs::path goldenDir() { return fs::path(SHADOWLAB_SOURCE_DIR) / "tests" / "goldens"; }

bool updating() {
  const char* env = std::getenv("SHADOWLAB_UPDATE_GOLDENS");
  return env && std::string(env) == "1";
}

// Top-down RGBA8 rows, as PNG files hold them.
std::vector<unsigned char> flipRows(const std::vector<unsigned char>& bottomUp, int w, int h) {
  std::vector<unsigned char> out(bottomUp.size());
  const size_t row = static_cast<size_t>(w) * 4;
  for (int y = 0; y < h; ++y)
    std::copy_n(&bottomUp[static_cast<size_t>(h - 1 - y) * row], row, &out[static_cast<size_t>(y) * row]);
  return out;
}

// Colour image with the visibility in alpha (255 = lit), top-down.
std::vector<unsigned char> renderPreset(test::GlHarness& h, const Scene& scene, const std::string& preset) {
  // The goldens of logpsm are the log warp alone: its perspective part (on by default) costs
  // minutes per image under the sanitizers' single-threaded llvmpipe, and has its own tests
  // (techniques/layouts/logpsm_test.cpp).
  std::vector<std::string> sets = {"shadowmap.size=512"};
  if (makeTechnique(preset).params.has("logpsm.perspective")) sets.push_back("logpsm.perspective=off");
  Viewport vp(makeTechnique(preset, sets));
  for (int f = 0; f < kFrames; ++f) {
    FrameInput in;
    in.camera = scene.cameras.front();
    in.width = kWidth;
    in.height = kHeight;
    in.cut = f == 0;
    h.renderer.render(in, {&vp});
  }
  std::vector<unsigned char> rgba = vp.colorTexture()->readRgba8();
  const std::vector<float> vis = vp.visibilityTexture()->readFloats(1);
  for (size_t i = 0; i < vis.size(); ++i)
    rgba[4 * i + 3] = static_cast<unsigned char>(std::lround(std::clamp(vis[i], 0.0f, 1.0f) * 255.0f));
  return flipRows(rgba, kWidth, kHeight);
}

struct Difference {
  double failing = 0, mean = 0;
  int max = 0;
};

Difference compare(const std::vector<unsigned char>& a, const unsigned char* b) {
  Difference d;
  long long failing = 0, sum = 0;
  const size_t pixels = a.size() / 4;
  for (size_t i = 0; i < pixels; ++i) {
    int worst = 0;
    for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(int(a[4 * i + c]) - int(b[4 * i + c])));
    failing += worst > kChannelTolerance ? 1 : 0;
    sum += worst;
    d.max = std::max(d.max, worst);
  }
  d.failing = double(failing) / double(pixels);
  d.mean = double(sum) / double(pixels);
  return d;
}

// One test per (scene, preset), so a failure names its case and each stays short.
struct GoldenCase {
  std::string scene, preset;
};

// ctest's test names carry the printed parameter.
void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.scene << " " << c.preset; }

std::vector<GoldenCase> goldenCases() {
  std::vector<GoldenCase> cases;
  for (const char* scene : {"basic", "columns", "spotlight", "dueling-frusta"})
    for (const Preset& preset : allPresets()) cases.push_back({scene, preset.id});
  return cases;
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, RendersAsBefore) {
  const GoldenCase& c = GetParam();
  test::GlHarness h;
  const Scene scene = loadScene(c.scene, defaultAssetsDir());
  h.renderer.setScene(scene);
  fs::create_directories(goldenDir());
  const std::vector<unsigned char> image = renderPreset(h, scene, c.preset);
  const fs::path file = goldenDir() / (c.scene + "-" + c.preset + ".png");
  if (updating()) {
    ASSERT_TRUE(stbi_write_png(file.string().c_str(), kWidth, kHeight, 4, image.data(), kWidth * 4)) << file;
    return;
  }
  int w = 0, hgt = 0, channels = 0;
  unsigned char* golden = stbi_load(file.string().c_str(), &w, &hgt, &channels, 4);
  ASSERT_TRUE(golden) << "no golden image " << file
                      << " (a new preset: render it with SHADOWLAB_UPDATE_GOLDENS=1, look at it, commit it)";
  EXPECT_EQ(w, kWidth);
  EXPECT_EQ(hgt, kHeight);
  if (w == kWidth && hgt == kHeight) {
    const Difference d = compare(image, golden);
    EXPECT_LE(d.failing, kFailingFraction) << "max channel difference " << d.max << ", mean " << d.mean;
    EXPECT_LE(d.mean, kMeanTolerance) << "failing fraction " << d.failing;
  }
  stbi_image_free(golden);
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

INSTANTIATE_TEST_SUITE_P(Scenes, Golden, ::testing::ValuesIn(goldenCases()), [](const auto& info) {
  std::string name = info.param.scene + "__" + info.param.preset;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
});

}  // namespace
}  // namespace sl
