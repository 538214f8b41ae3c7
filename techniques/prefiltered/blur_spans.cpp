#include "prefiltered/blur_spans.h"

#include "part/light_frame.h"

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

// The polygon's part with y >= y0 (keepAbove) or y <= y0 (Sutherland–Hodgman, one line).
std::vector<glm::vec2> clipAtRow(const std::vector<glm::vec2>& poly, float y0, bool keepAbove) {
  std::vector<glm::vec2> out;
  auto inside = [&](glm::vec2 p) { return keepAbove ? p.y >= y0 : p.y <= y0; };
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    if (inside(a)) out.push_back(a);
    if (inside(a) != inside(b)) {
      const float t = (y0 - a.y) / (b.y - a.y);
      out.push_back({a.x + t * (b.x - a.x), y0});
    }
  }
  return out;
}

}  // namespace

std::vector<glm::vec2> dilatedHull(const std::vector<glm::vec2>& hullUv, int size, float dilation) {
  // The hull of its corners moved by the dilation along both axes.
  std::vector<glm::vec2> corners;
  for (const glm::vec2& uv : hullUv)
    for (glm::vec2 d : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(-1, 1), glm::vec2(1, 1)})
      corners.push_back(uv * static_cast<float>(size) + d * dilation);
  return convexHull(corners);
}

std::vector<glm::ivec2> blurSpans(const std::vector<glm::vec2>& hullUv, int size, int band, float dilation) {
  if (hullUv.empty())
    return std::vector<glm::ivec2>(static_cast<size_t>((size + band - 1) / band), glm::ivec2(0, size - 1));
  return polygonSpans(dilatedHull(hullUv, size, dilation), size, band);
}

std::vector<glm::ivec2> polygonSpans(const std::vector<glm::vec2>& poly, int size, int band) {
  const int bands = (size + band - 1) / band;
  std::vector<glm::ivec2> spans(static_cast<size_t>(bands), glm::ivec2(1, 0));
  for (int b = 0; b < bands; ++b) {
    const std::vector<glm::vec2> slab =
        clipAtRow(clipAtRow(poly, static_cast<float>(b * band), true), static_cast<float>((b + 1) * band), false);
    // A texel is covered where the polygon's interior meets it ([x, x + 1) x [y, y + 1)): one
    // that only touches the band's edge covers none of its rows (the dilation, at least
    // kLookupReach in use, holds what lookups at the edge read).
    auto onRow = [&](float row) {
      return std::all_of(slab.begin(), slab.end(), [row](glm::vec2 p) { return p.y == row; });
    };
    if (slab.empty() || onRow(static_cast<float>(b * band)) || onRow(static_cast<float>((b + 1) * band))) continue;
    float lo = slab.front().x, hi = lo;
    for (const glm::vec2& p : slab) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    const int x0 = std::max(0, static_cast<int>(std::floor(lo)));
    const int x1 = std::min(size - 1, static_cast<int>(std::ceil(hi)) - 1);
    if (x0 <= x1) spans[static_cast<size_t>(b)] = {x0, x1};
  }
  return spans;
}

std::optional<std::vector<glm::ivec2>> columnIntervals(const std::vector<glm::ivec2>& rowSpans, int size) {
  std::vector<int> first(static_cast<size_t>(size), size), last(static_cast<size_t>(size), -1),
      count(static_cast<size_t>(size), 0);
  for (int y = 0; y < static_cast<int>(rowSpans.size()); ++y) {
    const int x0 = std::max(rowSpans[static_cast<size_t>(y)].x, 0);
    const int x1 = std::min(rowSpans[static_cast<size_t>(y)].y, size - 1);
    for (int x = x0; x <= x1; ++x) {
      first[static_cast<size_t>(x)] = std::min(first[static_cast<size_t>(x)], y);
      last[static_cast<size_t>(x)] = y;
      ++count[static_cast<size_t>(x)];
    }
  }
  std::vector<glm::ivec2> out(static_cast<size_t>(size), glm::ivec2(1, 0));
  for (size_t x = 0; x < out.size(); ++x) {
    if (count[x] == 0) continue;
    if (count[x] != last[x] - first[x] + 1) return std::nullopt;
    out[x] = {first[x], last[x]};
  }
  return out;
}

// The cells below are kBlurRun texels square and a group kBlurGroupSide cells by one, which is
// the shader's footprint (kBlurGroupSide runs of kBlurRun by kBlurGroupSide lines) only while
// the two are equal: runs of 16 or 32 alone would blur fewer texels than the lookups read.
static_assert(kBlurRun == kBlurGroupSide, "blurGroups assumes a run as long as a group's side");

BlurGroups blurGroups(const std::vector<glm::ivec2>& spans, int size, int apron) {
  // Cells of kBlurRun² texels: a second-direction group is one column of cells kBlurGroupSide
  // long (its lines are the cell's columns), a first-direction group one row of cells.
  const int cells = (size + kBlurRun - 1) / kBlurRun;
  const int groups = (cells + kBlurGroupSide - 1) / kBlurGroupSide;
  auto at = [cells](int cx, int cy) { return static_cast<size_t>(cy) * cells + cx; };
  std::vector<char> read(static_cast<size_t>(cells) * cells, 0);
  for (int cy = 0; cy < cells && cy < static_cast<int>(spans.size()); ++cy)
    if (spans[cy].x <= spans[cy].y)
      for (int cx = std::max(0, spans[cy].x / kBlurRun); cx <= std::min(cells - 1, spans[cy].y / kBlurRun); ++cx)
        read[at(cx, cy)] = 1;
  BlurGroups out;
  std::vector<char> made(read.size(), 0);  // cells the second direction makes
  for (int gy = 0; gy < cells; ++gy)       // a column of cells (gy = cx)
    for (int gx = 0; gx < groups; ++gx) {  // kBlurGroupSide cells down it
      const int y0 = gx * kBlurGroupSide, y1 = std::min(cells, y0 + kBlurGroupSide);
      bool needed = false;
      for (int cy = y0; cy < y1 && !needed; ++cy) needed = read[at(gy, cy)] != 0;
      if (!needed) continue;
      out.second.push_back({gx, gy});
      for (int cy = y0; cy < y1; ++cy) made[at(gy, cy)] = 1;
    }
  // The first direction's texels the second reads: the cells made, apron rows up and down.
  const int reach = (apron + kBlurRun - 1) / kBlurRun;
  for (int gy = 0; gy < cells; ++gy)       // a row of cells (gy = cy)
    for (int gx = 0; gx < groups; ++gx) {  // kBlurGroupSide cells along it
      bool needed = false;
      for (int cx = gx * kBlurGroupSide; cx < std::min(cells, (gx + 1) * kBlurGroupSide) && !needed; ++cx)
        for (int cy = std::max(0, gy - reach); cy <= std::min(cells - 1, gy + reach) && !needed; ++cy)
          needed = made[at(cx, cy)] != 0;
      if (needed) out.first.push_back({gx, gy});
    }
  long long texels = 0;
  for (const glm::uvec2& g : out.second) {
    const long long rows = std::min(size, static_cast<int>(g.x + 1) * kBlurGroupSide * kBlurRun) -
                           static_cast<long long>(g.x) * kBlurGroupSide * kBlurRun;
    const long long columns =
        std::min(size, static_cast<int>(g.y + 1) * kBlurRun) - static_cast<long long>(g.y) * kBlurRun;
    texels += rows * columns;
  }
  out.share = static_cast<double>(texels) / (static_cast<double>(size) * size);
  return out;
}

}  // namespace sl
