// One description of a line plot (title, axes, series, marker lines) that three drawers share:
// SVG files (`shadowlab plot`, figures' companions), the CPU image of a headless figure
// (tour/figure_plot.h) and the explorer's ImGui windows (explorer/plot_window.h). Producers (the
// dp/ds curves, visibility against receiver depth) build a Plot once; no drawer knows what the
// curves mean.
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace sl {

struct PlotSeries {
  std::string label;
  glm::vec3 colour{0.0f};
  std::vector<glm::vec2> points;  // (x, y) in data units; a non-finite or (log axis) non-positive value breaks the line
  float width = 1.5f;             // stroke width in pixels of a 720-pixel-wide plot
};

struct PlotAxis {
  std::string label;
  bool log = false;
  float lo = 0.0f, hi = 0.0f;  // the range shown; lo >= hi: fitted to the data (log axes to whole decades)
  std::vector<float> ticks;    // grid lines with labels; empty: decades (log) or five even steps (linear)
};

struct Plot {
  std::string title;
  PlotAxis x, y;
  std::vector<PlotSeries> series;
  std::vector<float> markers;  // x positions of dashed vertical lines (e.g. this pixel's receiver depth)
  std::string note;            // a line under the axis label (what the markers mean)
  bool empty() const { return series.empty(); }
};

// A plot's resolved ranges and ticks, and the mapping of data to the unit square (0,0 = bottom
// left). Every drawer uses it, so the three outputs show the same axes.
struct PlotFrame {
  struct Tick {
    float at;  // position along the axis in [0, 1]
    std::string label;
  };
  float xLo = 0, xHi = 1, yLo = 0, yHi = 1;
  bool xLog = false, yLog = false;
  std::vector<Tick> xTicks, yTicks;
  // (x, y) in [0, 1]^2 when inside the ranges; values outside are clamped to the border.
  glm::vec2 unit(glm::vec2 p) const;
  bool drawable(glm::vec2 p) const;  // finite, and positive on a log axis
  // The polylines of one series in unit coordinates, split where a point is not drawable.
  std::vector<std::vector<glm::vec2>> strokes(const PlotSeries& s) const;
};

PlotFrame resolvePlot(const Plot& plot);

// "#rrggbb".
std::string hexColour(glm::vec3 c);
// Text for SVG and HTML: & < > " escaped (every SVG and HTML report writes through it).
std::string xmlEscaped(const std::string& text);
// A standalone SVG of `width` x `height` pixels: white background, grid, curves, legend on the right.
std::string plotSvg(const Plot& plot, int width = 720, int height = 420);
// Writes plotSvg to `path`; throws std::runtime_error naming the path when it cannot.
void writePlotSvg(const Plot& plot, const std::string& path);
// A categorical colour for curve k (the same in every drawer).
glm::vec3 plotColour(size_t k);
// A series' colour on a dark background: near black (meant for white paper, the "true" curves)
// becomes near white; every other colour stays.
glm::vec3 plotColourOnDark(glm::vec3 c);
// A series of `values` at evenly spaced x over [0, 1] (curves sampled over depth).
PlotSeries evenlySpacedSeries(std::string label, glm::vec3 colour, float width, const std::vector<float>& values);

}  // namespace sl
