// The plot description every drawer shares (plot/plot.h): ranges fitted to the data (log axes to
// whole decades), ticks, strokes broken where a value cannot be drawn, the SVG's legend; the
// figure drawer puts each series' colour inside the plot's rectangle; a tour step's plot is
// drawn under a figure's panels (both kinds: dp/ds on the CPU, visibility through the GPU).
#include "gl_test_util.h"
#include "plot/plot.h"
#include "tour/figure.h"
#include "tour/figure_plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace sl {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

Plot twoSeries() {
  Plot p;
  p.title = "t";
  p.x = {.label = "x", .log = true};
  p.y = {.label = "y", .lo = -0.2f, .hi = 1.2f, .ticks = {0.0f, 0.5f, 1.0f}};
  p.series.push_back({.label = "a<b", .colour = {1, 0, 0}, .points = {{0.3f, 0.0f}, {3.0f, 0.5f}, {30.0f, 1.0f}}});
  p.series.push_back({.label = "gap",
                      .colour = {0, 0, 1},
                      .points = {{0.5f, 0.2f}, {1.0f, 0.3f}, {2.0f, kNaN}, {4.0f, 0.4f}, {8.0f, 0.5f}, {-1.0f, 0.6f}}});
  return p;
}

TEST(Plot, LogAxesFitWholeDecadesAndLinearAxesKeepTheirRange) {
  const PlotFrame f = resolvePlot(twoSeries());
  EXPECT_FLOAT_EQ(f.xLo, 0.1f);
  EXPECT_FLOAT_EQ(f.xHi, 100.0f);
  ASSERT_EQ(f.xTicks.size(), 4u);  // 0.1, 1, 10, 100
  EXPECT_EQ(f.xTicks[1].label, "1");
  EXPECT_NEAR(f.xTicks[1].at, 1.0f / 3.0f, 1e-5f);
  EXPECT_FLOAT_EQ(f.yLo, -0.2f);
  ASSERT_EQ(f.yTicks.size(), 3u);
  EXPECT_NEAR(f.yTicks[1].at, 0.5f, 1e-5f);  // 0.5 is the middle of [-0.2, 1.2]
  const glm::vec2 u = f.unit({10.0f, 1.2f});
  EXPECT_NEAR(u.x, 2.0f / 3.0f, 1e-5f);
  EXPECT_NEAR(u.y, 1.0f, 1e-5f);
  EXPECT_EQ(f.unit({1e6f, 5.0f}), glm::vec2(1.0f));  // clamped to the border
}

TEST(Plot, StrokesBreakAtValuesThatCannotBeDrawn) {
  const Plot p = twoSeries();
  const PlotFrame f = resolvePlot(p);
  EXPECT_EQ(f.strokes(p.series[0]).size(), 1u);
  // NaN breaks the line; a negative x on a log axis too (and a lone point draws no line).
  const auto strokes = f.strokes(p.series[1]);
  ASSERT_EQ(strokes.size(), 2u);
  EXPECT_EQ(strokes[0].size(), 2u);
  EXPECT_EQ(strokes[1].size(), 2u);
  // No data at all: still a frame with ranges, no crash.
  Plot empty;
  empty.x.log = true;
  const PlotFrame e = resolvePlot(empty);
  EXPECT_LT(e.xLo, e.xHi);
}

TEST(Plot, SvgHasALegendEntryPerSeriesAndEscapesText) {
  const std::string svg = plotSvg(twoSeries());
  EXPECT_NE(svg.find(">a&lt;b<"), std::string::npos);
  EXPECT_NE(svg.find(">gap<"), std::string::npos);
  EXPECT_NE(svg.find("#ff0000"), std::string::npos);
  size_t lines = 0;
  for (size_t at = svg.find("<polyline"); at != std::string::npos; at = svg.find("<polyline", at + 1)) ++lines;
  EXPECT_EQ(lines, 3u);  // one stroke + two strokes
}

// Pixels of exactly (or nearly) `colour` inside a rectangle of the image.
int pixelsNear(const RgbaImage& img, glm::vec3 colour, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = std::max(y0, 0); y < std::min(y1, img.height); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, img.width); ++x) {
      const uint8_t* p = &img.pixels[(size_t(y) * size_t(img.width) + size_t(x)) * 4];
      n += glm::length(glm::vec3(p[0], p[1], p[2]) / 255.0f - colour) < 0.12f;
    }
  return n;
}

TEST(Plot, FigureDrawerPutsEachCurveInsideItsRectangle) {
  RgbaImage img(400, 260, glm::vec3(0.09f));
  FigureFonts fonts(12.0f, 16.0f);
  drawFigurePlot(img, fonts, twoSeries(), 20, 20, 360, 220);
  EXPECT_GT(pixelsNear(img, {1, 0, 0}, 20, 20, 380, 240), 100);  // the red curve and its legend
  EXPECT_GT(pixelsNear(img, {0, 0, 1}, 20, 20, 380, 240), 50);
  EXPECT_EQ(pixelsNear(img, {1, 0, 0}, 0, 0, 400, 18), 0);  // nothing above the rectangle
}

TEST(Plot, TourStepPlotsAreDrawnUnderTheFigurePanels) {
  test::GlHarness h;
  const Tour t = parseTour(R"({"steps": [
    {"title": "d", "scene": "columns", "viewports": ["lispsm"], "plot": {"kind": "dpds", "techniques": ["uniform", "lispsm"]}},
    {"title": "v", "scene": "overlap", "viewports": [{"technique": "vsm", "set": ["filter.width=5"]}],
     "plot": {"kind": "visibility", "techniques": ["vsm", "gaussian"]}},
    {"title": "none", "viewports": ["standard"]}]})",
                           "plots.json");
  FigureOptions o;
  o.panelWidth = 160;
  o.panelHeight = 90;
  const FigureResult dpds = renderTourFigure(t, 0, h.shaders, o);
  ASSERT_EQ(dpds.plot.series.size(), 3u);  // uniform, lispsm, ideal logarithmic
  const FigureResult vis = renderTourFigure(t, 1, h.shaders, o);
  ASSERT_EQ(vis.plot.series.size(), 3u);  // true, vsm, gaussian
  EXPECT_NE(vis.plot.series[0].label.find("box of 5"), std::string::npos) << "the step's shared override";
  const FigureResult none = renderTourFigure(t, 2, h.shaders, o);
  EXPECT_TRUE(none.plot.empty());
  EXPECT_GT(dpds.image.height, none.image.height + 150);  // room for the plot
  // The first curve's colour appears below the panels (the plot), not in the panel row.
  const int panelsBottom = none.image.height - 40;
  EXPECT_GT(pixelsNear(dpds.image, plotColour(0), 0, panelsBottom, dpds.image.width, dpds.image.height), 50);
}

}  // namespace
}  // namespace sl
