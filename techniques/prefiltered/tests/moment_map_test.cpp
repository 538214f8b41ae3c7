// The moment maps in the renderer: the filter passes against direct box averages, robustness
// to broken texels, the clear value, and every pre-filtered representation rendering finite
// visibility in [0,1] under every filter method, format, layout and accumulation.
#include "part/transient_textures.h"
#include "prefiltered/blur_spans.h"
#include "prefiltered/tests/convex_inside.h"
#include "prefiltered/tests/moment_probe.h"
#include "technique.h"

#include <random>
#include <utility>

namespace sl {
namespace {

using test::GlHarness;

using test::compose;

struct Map {
  Technique technique;
  std::unique_ptr<RepresentationState> base;
  MomentMapState* state = nullptr;
};

// A moment map of `size` x `size` texels, one layer, for the representation of `preset`.
Map momentMap(const std::string& preset, const std::vector<std::string>& sets, int size) {
  Map m{makeTechnique(preset, sets), nullptr, nullptr};
  m.base = m.technique.representation->createState();
  m.state = dynamic_cast<MomentMapState*>(m.base.get());
  m.state->configure(m.technique.params);
  m.state->prepare(size, 1, 1);
  return m;
}

// What the shadow pass leaves: one depth per texel.
void fillDepth(const Map& m, const std::vector<float>& depth) {
  const Texture2D& tex = *m.state->depthTexture();
  glTextureSubImage3D(tex.id(), 0, 0, 0, 0, tex.width(), tex.height(), 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
}

// VSM's moments (z, z^2) of each depth, as representationMoments makes them in 32-bit floats.
std::vector<float> vsmMoments(const std::vector<float>& depth) {
  std::vector<float> out;
  for (float z : depth) {
    out.push_back(z);
    out.push_back(z * z);
  }
  return out;
}

void runFilter(GlHarness& h, const Map& m, const std::vector<std::vector<glm::vec2>>& hulls = {}) {
  MomentMapState& s = *m.state;
  TransientTextures pool;  // the frame graph's lender, here without a graph
  std::vector<Texture2D*> scratch;
  for (const TextureDesc& d : s.scratchTargets())
    scratch.push_back(static_cast<Texture2D*>(pool.acquire(d, "test scratch")));
  s.filter(
      h.shaders, drawFullscreenTriangle, scratch,
      [&m](const Program& p, TextureUnits&) { setTechniqueUniforms(p, m.technique, LightSpace{}, Light{}); }, hulls);
}

// The box of width w (odd: w taps; even: w+1 taps with half-weight ends), clamped to the edge.
std::vector<double> boxBlur(const std::vector<float>& in, int n, int w, int channels, bool logSpace, double c) {
  std::vector<double> tmp(in.size()), out(in.size());
  auto pass = [&](const auto& src, auto& dst, int dx, int dy) {
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (int ch = 0; ch < channels; ++ch) {
          double sum = 0, weight = 0;
          for (int i = -w / 2; i <= w / 2; ++i) {
            double wt = std::clamp(0.5 * w + 0.5 - std::abs(i), 0.0, 1.0);
            int sx = std::clamp(x + dx * i, 0, n - 1), sy = std::clamp(y + dy * i, 0, n - 1);
            double v = src[(static_cast<size_t>(sy) * n + sx) * channels + ch];
            sum += wt * (logSpace ? std::exp(c * v) : v);
            weight += wt;
          }
          dst[(static_cast<size_t>(y) * n + x) * channels + ch] = logSpace ? std::log(sum / weight) / c : sum / weight;
        }
  };
  pass(in, tmp, 1, 0);
  pass(tmp, out, 0, 1);
  return out;
}

// Sizes that are no multiple of the blur's 8-texel runs, and a box wider than the map, check the
// runs' ends and the clamped edges as well as the interior.
TEST(MomentMap, BoxBlurEqualsTheDirectBoxAverage) {
  GlHarness h;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  for (auto [n, width] : {std::pair{32, 2}, {32, 3}, {37, 5}, {37, 8}, {21, 63}}) {
    Map m = momentMap("vsm", {"filter.width=" + std::to_string(width)}, n);
    std::vector<float> z(static_cast<size_t>(n) * n);
    for (float& d : z) d = depth(rng);
    fillDepth(m, z);
    runFilter(h, m);
    const std::vector<float> got = m.state->moments(0).readFloats(2);
    const std::vector<double> want = boxBlur(vsmMoments(z), n, width, 2, false, 0);
    double worst = 0;
    for (size_t i = 0; i < got.size(); ++i) worst = std::max(worst, std::abs(got[i] - want[i]));
    EXPECT_LT(worst, 2e-6) << "size " << n << ", width " << width;
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// With a receiver hull the blur equals the whole map's wherever a lookup near the hull reads
// (the spans the work groups are chosen from) and holds the clear value, the moments of an
// empty texel, where no group ran; a 150² map (no multiple of a group's 64 texels) and a slanted
// triangle.
TEST(MomentMap, BlurOverAHullEqualsTheWholeBlurWhereLookupsRead) {
  GlHarness h;
  const int n = 150, width = 5;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  Map m = momentMap("vsm", {"filter.width=" + std::to_string(width)}, n);
  std::vector<float> z(static_cast<size_t>(n) * n);
  for (float& d : z) d = depth(rng);
  fillDepth(m, z);
  const std::vector<glm::vec2> hull = {{0.2f, 0.1f}, {0.9f, 0.3f}, {0.3f, 0.8f}};
  runFilter(h, m, {hull});
  const std::vector<float> got = m.state->moments(0).readFloats(2);
  const std::vector<double> want = boxBlur(vsmMoments(z), n, width, 2, false, 0);
  const std::vector<glm::ivec2> spans = blurSpans(hull, n, kBlurRun, kLookupReach);
  const std::vector<float>& clear = m.state->clearValue();
  long long read = 0, cleared = 0;
  double worst = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const glm::ivec2 span = spans[static_cast<size_t>(y / kBlurRun)];
      const size_t i = 2 * (static_cast<size_t>(y) * n + x);
      if (x >= span.x && x <= span.y) {
        ++read;
        worst = std::max({worst, std::abs(got[i] - want[i]), std::abs(got[i + 1] - want[i + 1])});
      } else if (got[i] == clear[0] && got[i + 1] == clear[1]) {
        ++cleared;
      } else {  // a texel of a group that ran: filtered, though nothing reads it
        EXPECT_NEAR(got[i], want[i], 2e-6) << x << "," << y;
      }
    }
  EXPECT_LT(worst, 2e-6);
  EXPECT_GT(cleared, n * n / 5) << "the triangle leaves much of the map unread";
  EXPECT_GT(read, n * n / 4);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(MomentMap, EsmBlursInLogSpaceWithoutOverflow) {
  GlHarness h;
  const int n = 32;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  Map m = momentMap("esm", {"filter.width=5", "esm.exponent=300"}, n);
  std::vector<float> data(static_cast<size_t>(n) * n);
  for (auto& d : data) d = depth(rng);
  fillDepth(m, data);
  runFilter(h, m);
  const std::vector<float> got = m.state->moments(0).readFloats(1);
  const std::vector<double> want = boxBlur(data, n, 5, 1, true, 300.0);
  double worst = 0;
  for (size_t i = 0; i < got.size(); ++i) worst = std::max(worst, std::abs(got[i] - want[i]));
  EXPECT_LT(worst, 1e-5);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// Every texel's lookup through the real lookup code (probe_lookup.frag: four bilinear reads of
// each summed-area table), RGBA per texel.
std::vector<float> probeLookups(GlHarness& h, const Map& m, int n) {
  const std::string prelude = m.state->defines() + "#include \"" + m.technique.representation->glslModule() + "\"\n";
  Program& p = h.shaders.get({"sat probe",
                              {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "probe_lookup.frag"}},
                              prelude});
  EXPECT_TRUE(p.valid()) << p.error();
  Texture2D target(GL_RGBA32F, n, n, "sat probe");
  Framebuffer fbo("sat probe");
  fbo.attach({&target}, nullptr);
  fbo.bind();
  p.use();
  setTechniqueUniforms(p, m.technique, LightSpace{}, Light{});
  p.set("u_probeSize", glm::vec2(n, n));
  {
    TextureUnits units;
    m.state->bind(p, units);
    drawFullscreenTriangle();
  }
  return target.readFloats(4);
}

// The largest difference of the lookups' two VSM moments from the direct box average over the
// texels `where` accepts.
template <class Where>
double worstLookup(const std::vector<float>& got, const std::vector<double>& want, int n, Where where) {
  double worst = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      if (where(x, y))
        for (int c = 0; c < 2; ++c)
          worst = std::max(worst, std::abs(got[(static_cast<size_t>(y) * n + x) * 4 + c] -
                                           want[(static_cast<size_t>(y) * n + x) * 2 + c]));
  return worst;
}

// The summed-area table read through the real lookup (four bilinear reads) against the direct
// box average, at texel centres whose box lies inside the table (at the first row and column
// the lookup shrinks the box; README).
TEST(MomentMap, SummedAreaTableAgreesWithTheDirectBox) {
  GlHarness h(test::probeShaderDir());
  const int n = 48;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  for (int width : {1, 3, 5, 9, 15}) {
    Map m = momentMap("vsm", {"filter.method=sat", "filter.width=" + std::to_string(width)}, n);
    std::vector<float> z(static_cast<size_t>(n) * n);
    for (float& d : z) d = depth(rng);
    fillDepth(m, z);
    runFilter(h, m);
    // The offset the table subtracts, computed on the GPU: the mean of (z, z²) over every fourth
    // row (moment_sat.cpp: kMeanStride), here worked out on the CPU in double.
    glm::dvec2 mean(0.0);
    int texels = 0;
    for (int y = 0; y < n; y += 4)
      for (int x = 0; x < n; ++x, ++texels) {
        const float d = z[static_cast<size_t>(y) * n + x];
        mean += glm::dvec2(d, d * d);
      }
    mean /= static_cast<double>(texels);
    const glm::vec4 offset = m.state->satOffsetOf(0);
    EXPECT_NEAR(offset.x, mean.x, 1e-5) << "width " << width;
    EXPECT_NEAR(offset.y, mean.y, 1e-5) << "width " << width;
    EXPECT_GT(std::abs(offset.x - 0.5), 0.0) << "not a constant";
    const std::vector<double> want = boxBlur(vsmMoments(z), n, width, 2, false, 0);
    const int h0 = width / 2 + 1;
    const double worst = worstLookup(probeLookups(h, m, n), want, n,
                                     [&](int x, int y) { return x >= h0 && y >= h0 && x < n - h0 && y < n - h0; });
    EXPECT_LT(worst, 2e-5) << "width " << width;
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// With a receiver hull the tables cover only the texels lookups near it read (a slanted
// triangle's spans, moment_sat.cpp): there every lookup still equals the direct box average,
// and the share covered is well below the map. Beyond the spans the texels hold an earlier
// frame's sums (here: the whole map's tables, made first), which a lookup there would mix.
TEST(MomentMap, SummedAreaTableOverAHullAgreesWithTheDirectBoxWhereLookupsRead) {
  GlHarness h(test::probeShaderDir());
  const int n = 96;
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  const std::vector<glm::vec2> hull = {{0.3f, 0.15f}, {0.85f, 0.4f}, {0.35f, 0.8f}};
  for (int width : {3, 9, 15}) {
    Map m = momentMap("vsm", {"filter.method=sat", "filter.width=" + std::to_string(width)}, n);
    std::vector<float> z(static_cast<size_t>(n) * n);
    for (float& d : z) d = depth(rng);
    fillDepth(m, z);
    runFilter(h, m);  // the whole map's tables: what the texels beyond the spans keep
    for (float& d : z) d = depth(rng);
    fillDepth(m, z);
    const double share = m.state->filter(
        h.shaders, [] {}, {},
        [&m](const Program& p, TextureUnits&) { setTechniqueUniforms(p, m.technique, LightSpace{}, Light{}); }, {hull},
        false);
    EXPECT_LT(share, 0.6) << "width " << width;
    const std::vector<double> want = boxBlur(vsmMoments(z), n, width, 2, false, 0);
    const double worst = worstLookup(probeLookups(h, m, n), want, n, [&](int x, int y) {
      return test::insideHull(hull, (glm::vec2(x, y) + 0.5f) / float(n));
    });
    EXPECT_LT(worst, 2e-5) << "width " << width;
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(MomentMap, MipLevelIsTheTwoByTwoAverage) {
  GlHarness h;
  const int n = 16;
  Map m = momentMap("vsm", {"filter.method=mipmap", "filter.width=2"}, n);
  std::vector<float> z(static_cast<size_t>(n) * n);
  for (size_t i = 0; i < z.size(); ++i) z[i] = float((i * 37) % 101) / 101.0f;
  fillDepth(m, z);
  runFilter(h, m);
  const std::vector<float> data = vsmMoments(z);
  std::vector<float> level1(static_cast<size_t>(n / 2) * (n / 2) * 2);
  glGetTextureImage(m.state->moments(0).id(), 1, GL_RG, GL_FLOAT, static_cast<GLsizei>(level1.size() * 4),
                    level1.data());
  for (int y = 0; y < n / 2; ++y)
    for (int x = 0; x < n / 2; ++x)
      for (int c = 0; c < 2; ++c) {
        float sum = 0;
        for (int k = 0; k < 4; ++k) sum += data[((2 * y + (k >> 1)) * n + 2 * x + (k & 1)) * 2 + c];
        EXPECT_NEAR(level1[(y * (n / 2) + x) * 2 + c], sum / 4, 1e-6) << x << "," << y;
      }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// The largest moments a map can hold: EVSM's four warped moments at the largest exponent, of
// depths 0 and 1 side by side, stored in 16-bit floats. The moments are taken in 32-bit floats
// and blurred before they are stored; each stored value must still be finite (the exponent is
// clamped to what the format holds: maxWarpExponent).
TEST(MomentMap, ExtremeWarpedMomentsStayFiniteInSixteenBits) {
  GlHarness h;
  const int n = 24;
  for (const std::string width : {"1", "7"}) {
    Map m = momentMap(
        "evsm4", {"filter.width=" + width, "filter.format=float16", "evsm.exponent_pos=100", "evsm.exponent_neg=100"},
        n);
    std::vector<float> z(static_cast<size_t>(n) * n);
    for (size_t i = 0; i < z.size(); ++i) z[i] = (i / 3) % 2 == 0 ? 0.0f : 1.0f;
    fillDepth(m, z);
    runFilter(h, m);
    const std::vector<float> got = m.state->moments(0).readFloats(4);
    float largest = 0;
    for (size_t i = 0; i < got.size(); ++i) {
      ASSERT_TRUE(std::isfinite(got[i])) << "width " << width << ", texel " << i / 4 << " channel " << i % 4;
      largest = std::max(largest, std::abs(got[i]));
    }
    EXPECT_GT(largest, 1000.0f) << "width " << width << ": the exponent was not near the format's largest";
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// The blur sums its taps without checking them (moment_blur.comp): every representation's
// moments of any depth must be finite, in both formats, at the parameters' extremes, and so
// must their averages, a texel at 0 beside one at 1 on every row and column.
TEST(MomentMap, EveryRepresentationsMomentsStayFiniteAtItsExtremes) {
  GlHarness h;
  const int n = 20;
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"vsm", {"vsm.min_variance=0"}},      {"esm", {"esm.exponent=1000"}},
      {"evsm2", {"evsm.exponent_pos=100"}}, {"evsm4", {"evsm.exponent_pos=100", "evsm.exponent_neg=100"}},
      {"gaussian", {"filter.width=2"}},     {"ewgf", {"ewgf.exponent=100"}},
      {"msm", {"filter.width=2"}},          {"msm16", {"filter.width=2"}},
      {"lvsm", {"lvsm.layers=16"}},         {"convolution", {"convolution.terms=16"}}};
  std::vector<float> z(static_cast<size_t>(n) * n);
  for (size_t i = 0; i < z.size(); ++i) z[i] = (i / 3 + i / n) % 2 == 0 ? 0.0f : (i % 7 == 0 ? 0.5f : 1.0f);
  for (const auto& [preset, extremes] : cases)
    for (const std::string format : {"float16", "float32"}) {
      std::vector<std::string> sets = extremes;
      sets.push_back("filter.format=" + format);
      std::string named;  // every setting, for the failure message
      for (const std::string& set : sets) named += " " + set;
      Map m = momentMap(preset, sets, n);
      fillDepth(m, z);
      runFilter(h, m);
      for (int t = 0; t < m.state->config().targets(); ++t) {
        const std::vector<float> got = m.state->moments(t).readFloats(4);
        size_t bad = 0;
        for (float v : got) bad += std::isfinite(v) ? 0 : 1;
        EXPECT_EQ(bad, 0u) << preset << named << ", target " << t;
      }
    }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

TEST(MomentMap, ClearValueIsTheMomentsOfTheFarPlane) {
  test::GlHarness h(test::probeShaderDir());
  test::MomentProbe probe(h);
  std::vector<std::pair<std::string, std::string>> cases;
  for (const std::string preset :
       {"vsm", "esm", "evsm2", "evsm4", "convolution", "gaussian", "ewgf", "msm", "msm16", "lvsm"})
    cases.push_back({preset, "filter.format=float32"});
  cases.push_back({"convolution", "convolution.terms=7"});
  // The soft ones (always 32-bit summed-area tables): CSM-Z's 4M + 1 channels up to 8 targets.
  cases.push_back({"vssm", "vssm.bleed=0"});
  for (const std::string terms : {"1", "4", "7"}) cases.push_back({"convolution-soft", "csmz.terms=" + terms});
  for (const auto& [preset, extra] : cases) {
    Map m = momentMap(preset, {extra}, 8);
    const std::vector<float> want = m.state->clearValue();
    const std::vector<float> got = probe.moments(preset, {extra}, 1.0f);
    ASSERT_EQ(got.size(), want.size()) << preset;
    for (size_t i = 0; i < got.size(); ++i)
      if (static_cast<int>(i % 4) < m.state->config().channelsOf(static_cast<int>(i / 4)))
        EXPECT_NEAR(got[i], want[i], 1e-4f * std::max(1.0f, std::abs(want[i]))) << preset << " channel " << i;
  }
}

long long outsideUnit(const test::Frame& f) {
  long long n = 0;
  for (size_t i = 0; i < f.visibility.size(); i += 2)
    n += std::isfinite(f.visibility[i]) && f.visibility[i] >= 0.0f && f.visibility[i] <= 1.0f ? 0 : 1;
  return n;
}

// Every representation, every filter method and format, and the two layouts and accumulations
// that stress it (LiSPSM: perspective depth; pixel-correct: jittered maps) on scenes with thin
// casters and depth discontinuities. One test per (scene, representation): a failure names both.
struct SceneAndRepresentation {
  std::string scene, representation;
};
void PrintTo(const SceneAndRepresentation& c, std::ostream* os) { *os << c.scene << " " << c.representation; }

std::vector<SceneAndRepresentation> sceneRepresentationCases() {
  std::vector<SceneAndRepresentation> cases;
  for (const std::string scene : {"thin-casters", "spotlight", "columns"})
    for (const std::string rep : {"vsm", "esm", "evsm", "gaussian", "ewgf", "msm", "convolution", "lvsm"})
      cases.push_back({scene, rep});
  return cases;
}

class MomentMapEverywhere : public ::testing::TestWithParam<SceneAndRepresentation> {};

TEST_P(MomentMapEverywhere, RendersFiniteVisibilityForEveryMethodFormatAndLayout) {
  const auto& [sceneId, rep] = GetParam();
  GlHarness h;
  Scene scene = loadScene(sceneId, defaultAssetsDir());
  h.renderer.setScene(scene);
  for (const std::string method : {"blur", "mipmap", "sat"})
    for (const std::string format : {"float16", "float32"})
      for (const auto& [layout, accumulation] : std::vector<std::pair<std::string, std::string>>{
               {"focused", "none"}, {"lispsm", "none"}, {"uniform", "pixel-correct"}}) {
        if (method == "sat" && rep == "esm") continue;  // not offered: log-space averages are no sums
        Viewport vp(compose(layout, rep, accumulation,
                            {"shadowmap.size=128", "filter.method=" + method, "filter.format=" + format}));
        FrameInput in;
        in.camera = scene.cameras.front();
        in.width = 48;
        in.height = 32;
        h.renderer.render(in, {&vp});
        test::Frame f = test::readFrame(h.renderer, vp, in.width, in.height);
        EXPECT_EQ(outsideUnit(f), 0) << sceneId << " " << rep << " " << method << " " << format << " " << layout << " "
                                     << accumulation;
      }
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  EXPECT_EQ(glDebugErrorCount(), 0);
}

INSTANTIATE_TEST_SUITE_P(Cases, MomentMapEverywhere, ::testing::ValuesIn(sceneRepresentationCases()),
                         [](const auto& info) {
                           std::string name = info.param.scene + "__" + info.param.representation;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace sl
