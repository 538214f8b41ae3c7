// The accuracy panel's exports: the table as CSV, the error-vs-time chart as SVG.
#include "explorer/error_panel.h"
#include "plot/plot.h"
#include "explorer/explorer_state.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace sl {

namespace {

std::string number(double v, const char* format = "%.4g") {
  if (!std::isfinite(v)) return "";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

const char* const kSvgViewportColours[4] = {"#ffcd50", "#5acdff", "#8ce178", "#f082d2"};

// The metric columns of an accuracy row: wrong, image wrong (empty when NaN), false shadow,
// false light, rmse, non-finite.
std::string metricCells(const ErrorMetrics& m, double imageWrongPct) {
  return "," + number(m.wrongPixelPct) + "," + number(imageWrongPct) + "," + number(m.falseShadowPct) + "," +
         number(m.falseLightPct) + "," + number(m.rmse) + "," + std::to_string(m.nonfinite);
}

}  // namespace

std::string otherLightsCsvRows(int viewport, const std::string& config,
                               const std::vector<LightVisibilityError>& lights) {
  std::string out;
  for (size_t k = 0; k < lights.size(); ++k)
    if (lights[k].shadowed)
      out += std::to_string(viewport) + " light " + std::to_string(k + 2) + "," + csvField(config) +
             metricCells(lights[k].error, std::numeric_limits<double>::quiet_NaN()) + ",\n";
  return out;
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string chartPointsCsv(const std::vector<ChartPoint>& points) {
  std::string out = "configuration,ms_per_frame_median,ms_readings,wrong_pixel_pct,image_wrong_pct,on_pareto_front\n";
  const std::vector<size_t> front = paretoFront(points);
  for (size_t i = 0; i < points.size(); ++i) {
    const ChartPoint& p = points[i];
    const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
    out += csvField(p.config) + "," + number(p.ms) + "," + std::to_string(p.msReadings.size()) + "," +
           number(p.wrongPct) + "," + number(p.imageWrongPct) + "," + (onFront ? "yes" : "no") + "\n";
  }
  return out;
}

std::string chartPointsSvg(const std::vector<ChartPoint>& points) {
  const double width = 640, height = 400, left = 70, right = 620, top = 20, bottom = 340;
  double msMin = 1e30, msMax = -1e30, errMin = 1e30, errMax = -1e30;
  for (const ChartPoint& p : points) {
    msMin = std::min(msMin, p.ms), msMax = std::max(msMax, p.ms);
    errMin = std::min(errMin, p.wrongPct), errMax = std::max(errMax, p.wrongPct);
  }
  if (points.empty()) msMin = errMin = 0, msMax = errMax = 1;
  const ChartAxis x = chooseChartAxis(msMin, msMax, 0.01), y = chooseChartAxis(errMin, errMax, 0.01);
  auto sx = [&](double v) { return left + x.toUnit(v) * (right - left); };
  auto sy = [&](double v) { return bottom - y.toUnit(v) * (bottom - top); };
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (double t : x.ticks())
    svg << "<line x1=\"" << sx(t) << "\" y1=\"" << top << "\" x2=\"" << sx(t) << "\" y2=\"" << bottom
        << "\" stroke=\"#ddd\"/><text x=\"" << sx(t) << "\" y=\"" << bottom + 16 << "\" text-anchor=\"middle\">"
        << formatTick(t) << "</text>\n";
  for (double t : y.ticks())
    svg << "<line x1=\"" << left << "\" y1=\"" << sy(t) << "\" x2=\"" << right << "\" y2=\"" << sy(t)
        << "\" stroke=\"#ddd\"/><text x=\"" << left - 6 << "\" y=\"" << sy(t) + 4 << "\" text-anchor=\"end\">"
        << formatTick(t) << "</text>\n";
  svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << right - left << "\" height=\"" << bottom - top
      << "\" fill=\"none\" stroke=\"#666\"/>\n";
  svg << "<text x=\"" << (left + right) / 2 << "\" y=\"" << bottom + 34 << "\" text-anchor=\"middle\">ms per frame"
      << (x.log ? " (log)" : "") << ", median</text>\n";
  svg << "<text transform=\"translate(16," << (top + bottom) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">wrong pixels %" << (y.log ? " (log)" : "") << "</text>\n";
  const std::vector<size_t> front = paretoFront(points);
  if (!front.empty()) {
    svg << "<polyline fill=\"none\" stroke=\"#333\" stroke-dasharray=\"5,4\" points=\"";
    for (size_t k = 0; k < front.size(); ++k) {
      const ChartPoint& p = points[front[k]];
      const double xEnd = k + 1 < front.size() ? sx(points[front[k + 1]].ms) : right;
      svg << sx(p.ms) << "," << sy(p.wrongPct) << " " << xEnd << "," << sy(p.wrongPct) << " ";
    }
    svg << "\"/>\n";
  }
  for (const ChartPoint& p : points) {
    const char* colour = p.viewport >= 0 && p.viewport < 4 ? kSvgViewportColours[p.viewport] : "#999";
    svg << "<circle cx=\"" << sx(p.ms) << "\" cy=\"" << sy(p.wrongPct) << "\" r=\"5\" fill=\"" << colour
        << "\" stroke=\"#333\"><title>" << xmlEscaped(p.config) << "</title></circle>\n<text x=\"" << sx(p.ms) + 7
        << "\" y=\"" << sy(p.wrongPct) - 6 << "\" font-size=\"10\">" << xmlEscaped(p.config) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

std::string ErrorPanel::accuracyCsv(const ExplorerState& state) const {
  std::string out =
      "viewport,configuration,wrong_pixel_pct,image_wrong_pct,false_shadow_pct,false_light_pct,rmse,nonfinite,"
      "ms_own_passes_median\n";
  for (int i = 0; i < state.viewportCount && i < 4; ++i) {
    const ViewportAccuracy& va = viewports_[i];
    if (state.slots.size() <= size_t(i) || !state.slots[size_t(i)].viewport) continue;
    out += std::to_string(i + 1) + "," +
           csvField(va.haveMetrics ? va.config : configString(state.slots[size_t(i)].viewport->technique));
    if (va.haveMetrics)
      out += metricCells(va.metrics, va.image.imageWrongPct);
    else
      out += ",,,,,,";
    const double own = va.ownMs.median();
    out += "," + (own >= 0 ? number(own) : std::string()) + "\n";
    if (va.haveMetrics) out += otherLightsCsvRows(i + 1, va.config, va.otherLights);
  }
  out += "\n" + chartPointsCsv(points_);
  return out;
}

}  // namespace sl
