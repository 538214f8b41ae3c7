// Lecture tours: the parser's error classes (each message names the file, the step and the
// field), planned techniques, and every step of every shipped tour rendered headless as a
// figure without error or NaN.
#include "gl_test_util.h"
#include "shipped_tours.h"
#include "tour/figure.h"
#include "tour/step_plot.h"
#include "tour/tour.h"
#include "technique.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace sl {
namespace {

// A one-step tour around `step` (a JSON object's body).
std::string tourWith(const std::string& step) { return R"({"title": "t", "steps": [)" + step + "]}"; }

const char* kGoodStep = R"({"title": "ok", "scene": "basic", "viewports": ["standard"]})";

// The message of the TourError that parsing `text` throws ("" if it parses).
std::string parseError(const std::string& text) {
  try {
    parseTour(text, "lecture.json");
  } catch (const TourError& e) {
    return e.what();
  }
  return "";
}

void expectMessage(const std::string& message, const std::vector<std::string>& parts) {
  ASSERT_FALSE(message.empty()) << "parsed without error";
  for (const auto& p : parts) EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
}

std::vector<std::string> shippedTours() { return test::shippedTourFiles(); }

TEST(TourParse, GoodStepParsesWithDefaults) {
  const Tour t = parseTour(tourWith(kGoodStep), "lecture.json");
  ASSERT_EQ(t.steps.size(), 1u);
  EXPECT_EQ(t.steps[0].viewports[0].technique, "standard");
  EXPECT_EQ(t.steps[0].frames, std::vector<int>{1});
  EXPECT_TRUE(t.steps[0].built());
  EXPECT_EQ(t.steps[0].camera.kind, TourCamera::Kind::Scene);
}

// The dp/ds legend names a technique as the step's panels do (#23: it read "logpsm:logpsm...").
TEST(TourParse, PlotLegendUsesTheViewportTitles) {
  const Tour t = parseTour(tourWith(R"j({"title": "a", "viewports": [
      {"technique": "lispsm", "label": "LiSPSM (n_opt)"},
      {"technique": "logpsm", "label": "LogPSM, loose", "set": ["logpsm.max_error=16", "logpsm.tessellate=off"]}]})j"),
                           "lecture.json");
  const TourStep& s = t.steps[0];
  EXPECT_EQ(stepSeriesLabel(s, "lispsm"), "LiSPSM (n_opt)");
  EXPECT_EQ(stepSeriesLabel(s, "logpsm:logpsm.tessellate=off;logpsm.max_error=16"), "LogPSM, loose");
  EXPECT_EQ(stepSeriesLabel(s, "logpsm:logpsm.max_error=16"), "logpsm (logpsm.max_error=16)");
  EXPECT_EQ(stepSeriesLabel(s, "uniform"), "uniform");
}

// A step may show one of a viewport's views large instead of as a thumbnail (#23: four viewports'
// thumbnails were a few pixels of image); it must be one of that viewport's views.
TEST(TourParse, EnlargeNamesOneOfTheViewportsViews) {
  const Tour t = parseTour(tourWith(R"({"title": "a", "viewports": [
      {"technique": "vsm", "views": ["texels", "moments"], "enlarge": "moments"}, "pcf"]})"),
                           "lecture.json");
  EXPECT_EQ(t.steps[0].viewports[0].enlarged, "moments");
  EXPECT_EQ(t.steps[0].viewports[1].enlarged, "");
  expectMessage(parseError(tourWith(R"({"title": "a", "viewports": [
      {"technique": "vsm", "views": ["texels"], "enlarge": "moments"}]})")),
                {"lecture.json", "steps[0] (\"a\").viewports[0].enlarge",
                 "'moments' is not one of this viewport's views", "texels"});
}

TEST(TourParse, BadJsonNamesTheFile) {
  expectMessage(parseError("{\"steps\": ["), {"lecture.json", "invalid JSON"});
  // A number beyond double's range (the tour fuzzer's input "52e529") is an error, not a crash.
  expectMessage(parseError("52e529"), {"lecture.json", "invalid JSON", "finite"});
}

TEST(TourParse, UnknownFieldNamesStepAndKey) {
  const std::string two =
      R"({"steps": [)" + std::string(kGoodStep) + R"(, {"title": "second", "viewports": ["pcf"], "captoin": "x"}]})";
  expectMessage(parseError(two), {"lecture.json", "steps[1]", "\"second\"", "captoin", "allowed"});
  expectMessage(parseError(R"({"stepz": []})"), {"unknown key 'stepz'"});
}

TEST(TourParse, UnknownPresetNamesStepAndField) {
  expectMessage(parseError(tourWith(R"({"title": "a", "viewports": ["standrad"]})")),
                {"lecture.json", "steps[0]", "viewports[0].technique", "unknown technique 'standrad'", "requires"});
}

TEST(TourParse, BadParameterIsReportedThroughItsDeclaration) {
  expectMessage(
      parseError(tourWith(R"({"title": "a", "viewports": [{"technique": "pcf", "set": ["pcf.kernel=40"]}]})")),
      {"steps[0]", "viewports[0].set", "pcf.kernel"});
  expectMessage(parseError(tourWith(R"({"title": "a", "viewports": [{"technique": "pcf", "set": ["lispsm.n=z_n"]}]})")),
                {"viewports[0].set", "lispsm.n"});
}

TEST(TourParse, ViewMustBeOfferedByTheTechnique) {
  // `confidence` belongs to pixel-correct, not to the standard map.
  expectMessage(
      parseError(tourWith(R"({"title": "a", "viewports": [{"technique": "standard", "views": ["confidence"]}]})")),
      {"steps[0]", "viewports[0].views[0]", "no view 'confidence'", "aliasing"});
  EXPECT_EQ(
      parseError(tourWith(R"({"title": "a", "viewports": [{"technique": "pixel-correct", "views": ["confidence"]}]})")),
      "");
  EXPECT_EQ(parseError(tourWith(R"({"title": "a", "viewports": [{"technique": "vsm", "views": ["variance"]}]})")), "");
}

TEST(TourParse, StructuralErrors) {
  expectMessage(parseError(tourWith(R"({"title": "a", "viewports": []})")), {"viewports", "1 to 4"});
  expectMessage(parseError(tourWith(R"({"title": "a", "viewports": ["standard"], "frames": [20, 10]})")),
                {"frames[1]", "increase"});
  expectMessage(parseError(tourWith(R"({"title": "a", "viewports": ["standard"], "camera": {"position": [0, 1, 2]}})")),
                {"camera", "'target'"});
  expectMessage(parseError(tourWith(R"({"title": "a", "viewports": ["standard"], "plot": {"kind": "pie"}})")),
                {"plot.kind", "pie"});
  expectMessage(parseError(tourWith(R"({"viewports": ["standard"]})")), {"steps[0]", "missing 'title'"});
  expectMessage(parseError(R"({"steps": []})"), {"steps", "non-empty"});
  expectMessage(parseError(tourWith(R"({"title": "a", "viewports": ["standard"], "light": [0, 120]})")),
                {"light", "elevation"});
}

TEST(TourParse, ClaimsNameTheirViewportsAndMetric) {
  const Tour t = parseTour(tourWith(R"({"title": "a", "viewports": ["uniform", "standard"], "frames": [1, 5],
      "claims": [{"better": 2, "than": 1, "factor": 2, "metric": "false_light"}, {"converges": 1},
                 {"better": 1, "than": 2, "metric": "image_wrong"}]})"),
                           "lecture.json");
  ASSERT_EQ(t.steps[0].claims.size(), 3u);
  EXPECT_EQ(t.steps[0].claims[2].metric, TourClaim::Metric::ImageWrong);
  EXPECT_EQ(t.steps[0].claims[0].kind, TourClaim::Kind::Better);
  EXPECT_EQ(t.steps[0].claims[0].viewport, 2);
  EXPECT_EQ(t.steps[0].claims[0].than, 1);
  EXPECT_EQ(t.steps[0].claims[0].factor, 2.0);
  EXPECT_EQ(t.steps[0].claims[0].metric, TourClaim::Metric::FalseLight);
  EXPECT_EQ(t.steps[0].claims[1].kind, TourClaim::Kind::Converges);
  const std::string two = R"({"title": "a", "viewports": ["uniform", "standard"], "claims": [)";
  expectMessage(parseError(tourWith(two + R"({"better": 3, "than": 1}]})")), {"claims[0].better", "3"});
  expectMessage(parseError(tourWith(two + R"({"better": 1, "than": 1}]})")), {"claims[0].than", "itself"});
  expectMessage(parseError(tourWith(two + R"({"better": 1}]})")), {"claims[0]", "'than'"});
  expectMessage(parseError(tourWith(two + R"({"better": 1, "than": 2, "metric": "psnr"}]})")),
                {"claims[0].metric", "psnr", "image_wrong"});
  expectMessage(parseError(tourWith(two + R"({"better": 1, "than": 2, "factor": 0.5}]})")),
                {"claims[0].factor", "[1, 1000]"});
  expectMessage(parseError(tourWith(two + R"({"converges": 1}]})")), {"claims", "two frame counts"});
  expectMessage(parseError(tourWith(two + R"({"converges": 1, "better": 2}]})")), {"claims[0]", "either"});
}

TEST(TourParse, ErrorViewIsOfferedByEveryTechniqueAndPlotPointIsAShare) {
  const Tour t = parseTour(tourWith(R"({"title": "a", "scene": "overlap", "viewports": [{"technique": "vsm",
      "views": ["error"]}], "plot": {"kind": "visibility", "techniques": ["vsm"], "point": [0.25, 0.75]}})"),
                           "lecture.json");
  EXPECT_EQ(t.steps[0].viewports[0].views, std::vector<std::string>{"error"});
  EXPECT_EQ(t.steps[0].plot.point, glm::vec2(0.25f, 0.75f));
  const std::string plot =
      R"({"title": "a", "viewports": ["vsm"], "plot": {"kind": "visibility", "techniques": ["vsm"], )";
  expectMessage(parseError(tourWith(plot + R"("point": [0.5, 1.5]}})")), {"plot.point", "[0, 1]"});
  expectMessage(parseError(tourWith(plot + R"("point": [0.5, 0.5], "pixel": [3, 4]}})")), {"plot.point", "not both"});
}

TEST(TourParse, PlannedTechniqueMarksTheStepNotBuilt) {
  const Tour t = parseTour(
      tourWith(
          R"({"title": "a", "caption": "exact", "requires": ["planned-only"], "viewports": ["planned-only", "standard"]})"),
      "lecture.json");
  ASSERT_FALSE(t.steps[0].built());
  EXPECT_EQ(t.steps[0].missing, std::vector<std::string>{"planned-only"});
  EXPECT_NE(t.steps[0].shownCaption().find("Not built yet (planned-only)"), std::string::npos);
  EXPECT_NE(t.steps[0].shownCaption().find("exact"), std::string::npos);
  // Listed as planned but present: validated as usual.
  expectMessage(parseError(tourWith(
                    R"({"title": "a", "requires": ["pcf"], "viewports": [{"technique": "pcf", "set": ["nope=1"]}]})")),
                {"viewports[0].set", "nope"});
}

TEST(TourParse, SceneAndCameraAreResolvedPerStep) {
  const Tour t = parseTour(
      tourWith(R"({"title": "a", "scene": "basic", "camera": "nowhere", "viewports": ["standard"]})"), "lecture.json");
  const Scene scene = loadStepScene(t, 0, defaultAssetsDir());
  try {
    stepCamera(t, 0, scene);
    FAIL() << "unknown camera accepted";
  } catch (const TourError& e) {
    expectMessage(e.what(), {"lecture.json", "steps[0]", "camera", "nowhere", "top"});
  }
  const Tour missing =
      parseTour(tourWith(R"({"title": "a", "scene": "no-such-scene", "viewports": ["standard"]})"), "x.json");
  EXPECT_THROW(loadStepScene(missing, 0, defaultAssetsDir()), TourError);
}

TEST(TourParse, ShippedToursParseAndResolve) {
  const auto files = shippedTours();
  ASSERT_GE(files.size(), 3u);
  for (const auto& f : files) {
    const Tour t = loadTour(f);
    EXPECT_GE(t.steps.size(), 5u) << f;
    for (size_t i = 0; i < t.steps.size(); ++i) {
      const Scene scene = loadStepScene(t, i, defaultAssetsDir());
      EXPECT_NO_THROW(stepCamera(t, i, scene)) << f << " " << describeStep(t, i);
      EXPECT_FALSE(t.steps[i].caption.empty()) << f << " " << describeStep(t, i);
    }
  }
}

// Byte mutations of a shipped tour: whatever the damage, parsing ends in a TourError or a tour,
// never another exception or a crash (a fuzzer calls parseTour the same way).
TEST(TourParse, MutatedToursFailCleanly) {
  std::ifstream in(std::string(SHADOWLAB_SOURCE_DIR) + "/tours/pixel-correct.json");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(text.empty());
  const std::string replacements = "{}[]\",:0-9.eE\\ ax";
  uint32_t seed = 12345;
  auto next = [&seed] { return seed = seed * 1664525u + 1013904223u; };
  int parsed = 0, rejected = 0;
  for (int i = 0; i < 400; ++i) {
    std::string t = text;
    for (int k = 0; k < 1 + i % 3; ++k) t[next() % t.size()] = replacements[next() % replacements.size()];
    try {
      parseTour(t, "mutated.json");
      ++parsed;
    } catch (const TourError& e) {
      EXPECT_NE(std::string(e.what()).find("mutated.json"), std::string::npos) << e.what();
      ++rejected;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not a TourError: " << e.what();
    }
  }
  EXPECT_GT(rejected, 100);
  EXPECT_GT(parsed, 0);
}

// Every step of every shipped tour as a figure at 160x90 per panel (at most 3 frames, maps of at most 512² unless a
// step sets the size): renders, no NaN, no GL or shader error, and the figure holds a panel per image plus lit
// (non-background) pixels.
class ShippedTour : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedTour, EveryStepRendersAsAFigure) {
  test::GlHarness h;
  FigureOptions o;
  o.panelWidth = 160;
  o.panelHeight = 90;
  Tour t = loadTour(GetParam());
  for (size_t i = 0; i < t.steps.size(); ++i) {
    // A few frames keep the test short: long convergence runs capture at frames 1, 2, 3.
    std::vector<int>& frames = t.steps[i].frames;
    if (frames.back() > 3) {
      const size_t n = std::min<size_t>(frames.size(), 3);
      frames.clear();
      for (size_t k = 1; k <= n; ++k) frames.push_back(static_cast<int>(k));
    }
    // And 512² maps where a step keeps the default 2048² (pre-filtered maps blur every texel).
    for (auto& v : t.steps[i].viewports)
      if (std::none_of(v.overrides.begin(), v.overrides.end(),
                       [](const std::string& o) { return o.rfind("shadowmap.size=", 0) == 0; }))
        v.overrides.push_back("shadowmap.size=512");
    SCOPED_TRACE(GetParam() + " " + describeStep(t, i));
    const FigureResult r = renderTourFigure(t, i, h.shaders, o);
    EXPECT_EQ(r.nonfinitePixels, 0);
    EXPECT_TRUE(h.shaders.errors().empty());
    size_t expected = 0;
    for (const auto& v : t.steps[i].viewports)
      if (findPreset(v.technique)) expected += (1 + v.views.size()) * t.steps[i].frames.size();
    EXPECT_EQ(r.panels, static_cast<int>(expected));
    EXPECT_GE(r.image.width, o.panelWidth);
    EXPECT_GE(r.bodyPixels * 40.0f, float(r.image.height)) << "text under 1/40 of the figure's height";
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

INSTANTIATE_TEST_SUITE_P(Tours, ShippedTour, ::testing::ValuesIn(shippedTours()), test::tourTestName);

// Six panels (three viewports with a view each) make a grid near 16:9 (each viewport a column, its
// view under it), not a 6x1 strip; a portrait aspect makes a narrower one.
TEST(TourFigure, PanelsFormAGridNearTheAspectAskedFor) {
  test::GlHarness h;
  const Tour t = parseTour(tourWith(R"({"title": "Six", "scene": "basic", "viewports": [
      {"technique": "standard", "views": ["aliasing"]}, {"technique": "pcf", "views": ["aliasing"]},
      {"technique": "lispsm", "views": ["aliasing"]}]})"),
                           "six.json");
  FigureOptions o;
  o.panelWidth = 160;
  o.panelHeight = 90;
  const FigureResult wide = renderTourFigure(t, 0, h.shaders, o);
  EXPECT_EQ(wide.panels, 6);
  const float aspect = float(wide.image.width) / float(wide.image.height);
  // A 6x1 strip of these panels would be about 4:1 here.
  EXPECT_GT(aspect, 16.0f / 9.0f / 1.6f);
  EXPECT_LT(aspect, 16.0f / 9.0f * 1.6f);
  EXPECT_LT(wide.image.width, 6 * o.panelWidth) << "the panels should wrap into rows";
  EXPECT_GE(wide.bodyPixels * 40.0f, float(wide.image.height));
  o.aspect = 0.5f;  // portrait: the panels wrap into fewer columns
  const FigureResult square = renderTourFigure(t, 0, h.shaders, o);
  EXPECT_LT(float(square.image.width) / float(square.image.height), aspect);
}

TEST(TourFigure, CaptionAndPanelsAreBurntIn) {
  test::GlHarness h;
  const Tour t = parseTour(
      tourWith(R"({"title": "Title", "caption": "A caption long enough to wrap onto a second line in a small figure.",
      "scene": "basic", "frames": [1, 3], "viewports": [{"technique": "standard", "views": ["aliasing"]}]})"),
      "lecture.json");
  FigureOptions o;
  o.panelWidth = 120;
  o.panelHeight = 80;
  const FigureResult r = renderTourFigure(t, 0, h.shaders, o);
  EXPECT_EQ(r.panels, 4);  // colour + aliasing, at 1 and 3 frames
  EXPECT_GE(r.image.width, 2 * 120);
  EXPECT_GE(r.image.height, 2 * 80);
  // Text pixels: bright, near-white (r = g) pixels in the caption band below the panels.
  int bright = 0;
  for (int y = r.image.height - 30; y < r.image.height; ++y)
    for (int x = 0; x < r.image.width; ++x) {
      const uint8_t* p = &r.image.pixels[(size_t(y) * size_t(r.image.width) + size_t(x)) * 4];
      bright += p[0] > 150 && p[0] == p[1] ? 1 : 0;
    }
  EXPECT_GT(bright, 20) << "no caption text drawn";
}

}  // namespace
}  // namespace sl
