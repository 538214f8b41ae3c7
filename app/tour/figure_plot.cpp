// drawFigurePlot (see figure_plot.h): each segment is drawn by distance to it, which is plenty
// for curves of a few hundred points and needs no rasterizer.
#include "tour/figure_plot.h"

#include <algorithm>
#include <cmath>

namespace sl {
namespace {

const glm::vec3 kFrame{0.45f, 0.46f, 0.5f}, kGrid{0.22f, 0.23f, 0.26f}, kLabel{0.7f, 0.72f, 0.75f};

// Each pixel near the segment takes the colour by its coverage of a stroke `width` wide (distance
// from the pixel centre to the segment), so line centres get the exact colour.
void drawSegment(RgbaImage& img, glm::vec2 a, glm::vec2 b, glm::vec3 colour, float width) {
  const float r = std::max(width * 0.5f, 0.5f);
  const glm::vec2 lo = glm::min(a, b) - (r + 1.0f), hi = glm::max(a, b) + (r + 1.0f);
  const glm::vec2 ab = b - a;
  const float len2 = std::max(glm::dot(ab, ab), 1e-12f);
  for (int y = int(std::floor(lo.y)); y <= int(std::ceil(hi.y)); ++y)
    for (int x = int(std::floor(lo.x)); x <= int(std::ceil(hi.x)); ++x) {
      const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
      const float t = std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f);
      const float coverage = std::clamp(r + 0.5f - glm::length(p - (a + t * ab)), 0.0f, 1.0f);
      if (coverage > 0.0f) img.blend(x, y, colour, coverage);
    }
}

void dashedVertical(RgbaImage& img, int x, int y0, int y1, glm::vec3 colour) {
  for (int y = y0; y < y1; ++y)
    if ((y - y0) % 7 < 4) img.blend(x, y, colour, 1.0f);
}

}  // namespace

void drawFigurePlot(RgbaImage& img, const FigureFonts& fonts, const Plot& plot, int x, int y, int w, int h) {
  using Style = FigureFonts::Style;
  const PlotFrame f = resolvePlot(plot);
  const int body = fonts.lineHeight(Style::Body);
  const int legendW = std::max(w / 4, 120), tickW = fonts.width("0.001", Style::Body) + 6;
  const int left = x + tickW, right = x + w - legendW, top = y + body + 4;
  std::vector<std::string> under = fonts.wrap(plot.x.label + "; y: " + plot.y.label, w - (left - x), Style::Body);
  if (!plot.note.empty()) under.push_back(plot.note);
  const int bottom = y + h - body * (1 + int(under.size())) - 4;
  if (right - left < 40 || bottom - top < 30) return;  // too small to read
  fonts.draw(img, x, y, plot.title, Style::Body, glm::vec3(0.92f));
  auto px = [&](glm::vec2 u) {
    return glm::vec2(float(left) + u.x * float(right - left), float(bottom) - u.y * float(bottom - top));
  };
  for (const auto& t : f.yTicks) {
    const int ty = int(std::round(px({0, t.at}).y));
    img.fillRect(left, ty, right - left, 1, kGrid);
    fonts.draw(img, x, ty - body / 2, t.label, Style::Body, kLabel);
  }
  for (const auto& t : f.xTicks) {
    const int tx = int(std::round(px({t.at, 0}).x));
    const int lw = fonts.width(t.label, Style::Body);
    fonts.draw(img, std::clamp(tx - lw / 2, x, x + w - lw), bottom + 2, t.label, Style::Body, kLabel);
  }
  img.fillRect(left, top, right - left, 1, kFrame), img.fillRect(left, bottom, right - left, 1, kFrame);
  img.fillRect(left, top, 1, bottom - top, kFrame), img.fillRect(right, top, 1, bottom - top + 1, kFrame);
  for (float m : plot.markers) dashedVertical(img, int(std::round(px(f.unit({m, f.yLo})).x)), top, bottom, kLabel);
  for (size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& s = plot.series[k];
    const glm::vec3 colour = plotColourOnDark(s.colour);
    for (const auto& stroke : f.strokes(s))
      for (size_t i = 1; i < stroke.size(); ++i) drawSegment(img, px(stroke[i - 1]), px(stroke[i]), colour, s.width);
    const int ly = top + int(k) * body;
    img.fillRect(right + 8, ly + body / 2, 14, 2, colour);
    fonts.draw(img, right + 26, ly, s.label, Style::Body, colour);
  }
  for (size_t i = 0; i < under.size(); ++i)
    fonts.draw(img, left, bottom + (int(i) + 1) * body + 2, under[i], Style::Body, kLabel);
}

}  // namespace sl
