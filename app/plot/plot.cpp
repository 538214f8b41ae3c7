// PlotFrame and the SVG drawer (see plot.h).
#include "plot/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sl {
namespace {

std::string number(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", double(v));
  return text;
}

std::string decadeLabel(int d) {
  if (d >= -2 && d <= 3) return number(std::pow(10.0f, float(d)));
  return "1e" + std::to_string(d);
}

// The axis's range: as given, or fitted to the data (log axes out to whole decades).
void fitRange(const PlotAxis& axis, const std::vector<float>& values, float& lo, float& hi) {
  if (axis.lo < axis.hi) {
    lo = axis.lo, hi = axis.hi;
    return;
  }
  lo = 1e30f, hi = -1e30f;
  for (float v : values) lo = std::min(lo, v), hi = std::max(hi, v);
  if (lo > hi) lo = axis.log ? 0.1f : 0.0f, hi = axis.log ? 10.0f : 1.0f;  // no data
  if (axis.log) {
    lo = std::pow(10.0f, std::floor(std::log10(lo)));
    hi = std::pow(10.0f, std::ceil(std::log10(hi)));
    if (hi <= lo) hi = lo * 10.0f;
  } else if (hi <= lo) {
    hi = lo + 1.0f;
  }
}

std::vector<PlotFrame::Tick> ticksOf(const PlotAxis& axis, float lo, float hi, bool log) {
  auto at = [&](float v) {
    return log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : (v - lo) / (hi - lo);
  };
  std::vector<PlotFrame::Tick> ticks;
  if (!axis.ticks.empty()) {
    for (float v : axis.ticks)
      if (v >= lo && v <= hi && (!log || v > 0.0f)) ticks.push_back({at(v), number(v)});
    return ticks;
  }
  if (log) {
    for (int d = int(std::ceil(std::log10(lo) - 1e-4f)); d <= int(std::floor(std::log10(hi) + 1e-4f)); ++d)
      ticks.push_back({at(std::pow(10.0f, float(d))), decadeLabel(d)});
    return ticks;
  }
  for (int k = 0; k <= 4; ++k) ticks.push_back({float(k) / 4.0f, number(lo + (hi - lo) * float(k) / 4.0f)});
  return ticks;
}

}  // namespace

std::string xmlEscaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

glm::vec3 plotColour(size_t k) {
  static const glm::vec3 colours[] = {{0.85f, 0.25f, 0.17f}, {0.91f, 0.64f, 0.09f}, {0.23f, 0.62f, 0.23f},
                                      {0.23f, 0.49f, 0.85f}, {0.54f, 0.36f, 0.78f}, {0.17f, 0.69f, 0.69f},
                                      {0.89f, 0.47f, 0.76f}, {0.55f, 0.34f, 0.29f}};
  return colours[k % (sizeof colours / sizeof *colours)];
}

glm::vec3 plotColourOnDark(glm::vec3 c) {
  return glm::dot(c, glm::vec3(0.3f, 0.59f, 0.11f)) < 0.05f ? glm::vec3(0.95f) : c;
}

PlotSeries evenlySpacedSeries(std::string label, glm::vec3 colour, float width, const std::vector<float>& values) {
  PlotSeries s{.label = std::move(label), .colour = colour, .width = width};
  for (size_t i = 0; i < values.size(); ++i)
    s.points.emplace_back(float(i) / float(std::max<size_t>(values.size() - 1, 1)), values[i]);
  return s;
}

std::string hexColour(glm::vec3 c) {
  char text[8];
  auto byte = [](float v) { return int(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); };
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return text;
}

bool PlotFrame::drawable(glm::vec2 p) const {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  return (!xLog || p.x > 0.0f) && (!yLog || p.y > 0.0f);
}

glm::vec2 PlotFrame::unit(glm::vec2 p) const {
  auto map = [](float v, float lo, float hi, bool log) {
    const float t = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : (v - lo) / (hi - lo);
    return std::clamp(t, 0.0f, 1.0f);
  };
  return {map(p.x, xLo, xHi, xLog), map(p.y, yLo, yHi, yLog)};
}

std::vector<std::vector<glm::vec2>> PlotFrame::strokes(const PlotSeries& s) const {
  std::vector<std::vector<glm::vec2>> out(1);
  for (glm::vec2 p : s.points) {
    if (!drawable(p)) {
      if (!out.back().empty()) out.emplace_back();
      continue;
    }
    out.back().push_back(unit(p));
  }
  std::erase_if(out, [](const auto& stroke) { return stroke.size() < 2; });
  return out;
}

PlotFrame resolvePlot(const Plot& plot) {
  PlotFrame f;
  f.xLog = plot.x.log, f.yLog = plot.y.log;
  std::vector<float> xs, ys;
  for (const PlotSeries& s : plot.series)
    for (glm::vec2 p : s.points)
      if (f.drawable(p)) xs.push_back(p.x), ys.push_back(p.y);
  fitRange(plot.x, xs, f.xLo, f.xHi);
  fitRange(plot.y, ys, f.yLo, f.yHi);
  f.xTicks = ticksOf(plot.x, f.xLo, f.xHi, f.xLog);
  f.yTicks = ticksOf(plot.y, f.yLo, f.yHi, f.yLog);
  return f;
}

std::string plotSvg(const Plot& plot, int width, int height) {
  const PlotFrame f = resolvePlot(plot);
  const float W = float(width), H = float(height), left = 60, right = 200, top = 36,
              bottom = plot.note.empty() ? 46 : 62;
  auto X = [&](float u) { return left + u * (W - left - right); };
  auto Y = [&](float u) { return H - bottom - u * (H - top - bottom); };
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << left << "\" y=\"22\" font-size=\"14\">" << xmlEscaped(plot.title) << "</text>\n";
  for (const auto& t : f.yTicks)
    s << "<line x1=\"" << X(0) << "\" x2=\"" << X(1) << "\" y1=\"" << Y(t.at) << "\" y2=\"" << Y(t.at)
      << "\" stroke=\"#ddd\"/><text x=\"" << left - 6 << "\" y=\"" << Y(t.at) + 4 << "\" text-anchor=\"end\">"
      << t.label << "</text>\n";
  for (const auto& t : f.xTicks)
    s << "<text x=\"" << X(t.at) << "\" y=\"" << Y(0) + 15 << "\" text-anchor=\"middle\">" << t.label << "</text>\n";
  s << "<rect x=\"" << X(0) << "\" y=\"" << Y(1) << "\" width=\"" << X(1) - X(0) << "\" height=\"" << Y(0) - Y(1)
    << "\" fill=\"none\" stroke=\"#999\"/>\n";
  for (float m : plot.markers) {
    const float u = f.unit({m, f.yLo}).x;
    s << "<line x1=\"" << X(u) << "\" x2=\"" << X(u) << "\" y1=\"" << Y(0) << "\" y2=\"" << Y(1)
      << "\" stroke=\"#999\" stroke-dasharray=\"4 3\"/>\n";
  }
  s << "<text x=\"" << left << "\" y=\"" << H - bottom + 32 << "\">" << xmlEscaped(plot.x.label)
    << "; y: " << xmlEscaped(plot.y.label) << "</text>\n";
  if (!plot.note.empty())
    s << "<text x=\"" << left << "\" y=\"" << H - 10 << "\">" << xmlEscaped(plot.note) << "</text>\n";
  for (size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& series = plot.series[k];
    const std::string colour = hexColour(series.colour);
    for (const auto& stroke : f.strokes(series)) {
      s << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << series.width << "\" points=\"";
      for (glm::vec2 p : stroke) s << X(p.x) << "," << Y(p.y) << " ";
      s << "\"/>\n";
    }
    s << "<text x=\"" << W - right + 10 << "\" y=\"" << top + 18 * (k + 1) << "\" fill=\"" << colour << "\">"
      << xmlEscaped(series.label) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

void writePlotSvg(const Plot& plot, const std::string& path) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot write");
  f << plotSvg(plot);
  if (!f) throw std::runtime_error(path + ": write failed");
}

}  // namespace sl
