#include "adaptive/quadtree_fit.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sl {

int fitGridSide(int pagesPerSide) { return std::min(pagesPerSide, kMaxFitGrid); }

namespace {

// Min-need and sample-count pyramids over the grid: level k of the pyramid has G >> k cells per
// side, each the finest need (smallest level; `none` without samples) and the pixels below it.
struct Pyramid {
  static constexpr int none = 1 << 20;
  std::vector<std::vector<int>> need;
  std::vector<std::vector<uint64_t>> count;
  int side(int k) const { return static_cast<int>(1u << (need.size() - 1 - static_cast<size_t>(k))); }
};

Pyramid buildPyramid(const std::vector<uint32_t>& grid, int g, int levels) {
  Pyramid p;
  const size_t cells = static_cast<size_t>(g) * static_cast<size_t>(g);
  p.need.push_back(std::vector<int>(cells));
  p.count.push_back(std::vector<uint64_t>(cells));
  for (size_t c = 0; c < cells; ++c) {
    const uint32_t finer = std::min<uint32_t>(grid[c], static_cast<uint32_t>(levels));
    p.need[0][c] = finer == 0u ? Pyramid::none : levels - static_cast<int>(finer);
    p.count[0][c] = finer == 0u ? 0u : std::max<uint64_t>(grid[cells + c], 1u);
  }
  for (int n = g / 2; n >= 1; n /= 2) {
    const auto& fineNeed = p.need.back();
    const auto& fineCount = p.count.back();
    std::vector<int> need(static_cast<size_t>(n) * static_cast<size_t>(n), Pyramid::none);
    std::vector<uint64_t> count(need.size(), 0u);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (int k = 0; k < 4; ++k) {
          const size_t f = static_cast<size_t>((2 * y + k / 2) * 2 * n + 2 * x + k % 2);
          const size_t c = static_cast<size_t>(y * n + x);
          need[c] = std::min(need[c], fineNeed[f]);
          count[c] += fineCount[f];
        }
    p.need.push_back(std::move(need));
    p.count.push_back(std::move(count));
  }
  return p;
}

struct Traversal {
  const PageAllocator& pages;
  const Pyramid& pyramid;
  int cellLevel;  // page level of one grid cell (0 when the grid has a cell per level-0 page)
  QuadtreeFit& out;

  // A node finer than a grid cell takes its cell's need and samples.
  void visit(int level, int x, int y) {
    const int k = std::max(level - cellLevel, 0), shift = std::max(cellLevel - level, 0);
    const size_t c = static_cast<size_t>((y >> shift) * pyramid.side(k) + (x >> shift));
    const uint64_t samples = pyramid.count[static_cast<size_t>(k)][c];
    if (samples == 0u) return;  // nothing visible under it: no page
    ++out.nodesVisited;
    if (pyramid.need[static_cast<size_t>(k)][c] >= level || level == 0) {
      out.marks[static_cast<size_t>(pages.encode(level, x, y))] =
          static_cast<uint32_t>(std::min<uint64_t>(samples, 0xffffffffu));
      ++out.leaves;
      out.finestLevel = out.finestLevel < 0 ? level : std::min(out.finestLevel, level);
      return;
    }
    for (int child = 0; child < 4; ++child) visit(level - 1, 2 * x + child % 2, 2 * y + child / 2);
  }
};

}  // namespace

QuadtreeFit fitQuadtree(const PageAllocator& pages, const std::vector<uint32_t>& grid) {
  const int g = fitGridSide(pages.pagesPerSide());
  const size_t expected = 2u * static_cast<size_t>(g) * static_cast<size_t>(g);
  if (g < 1 || grid.size() != expected)
    throw std::invalid_argument("fitted virtual shadow map: the fit grid holds " + std::to_string(grid.size()) +
                                " values, expected " + std::to_string(expected) + " (2 x " + std::to_string(g) + "²)");
  QuadtreeFit out;
  out.marks.assign(static_cast<size_t>(pages.flatSize()), 0u);
  int cellLevel = 0;
  while ((g << cellLevel) < pages.pagesPerSide()) ++cellLevel;
  const Pyramid pyramid = buildPyramid(grid, g, pages.levels());
  Traversal{pages, pyramid, cellLevel, out}.visit(pages.levels() - 1, 0, 0);
  return out;
}

}  // namespace sl
