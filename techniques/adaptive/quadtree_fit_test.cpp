// The CPU quadtree of fitted virtual shadow maps, checked against trees worked out by hand.
#include "adaptive/quadtree_fit.h"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

namespace sl {
namespace {

// A fit grid for `a` with samples: (cell x, cell y, needed level, pixels).
std::vector<uint32_t> gridOf(const PageAllocator& a, const std::vector<std::tuple<int, int, int, int>>& samples) {
  const int g = fitGridSide(a.pagesPerSide());
  std::vector<uint32_t> grid(2u * static_cast<size_t>(g * g), 0u);
  for (auto [x, y, level, pixels] : samples) {
    const size_t c = static_cast<size_t>(y * g + x);
    grid[c] = std::max(grid[c], static_cast<uint32_t>(a.levels() - level));
    grid[static_cast<size_t>(g * g) + c] += static_cast<uint32_t>(pixels);
  }
  return grid;
}

std::set<std::tuple<int, int, int>> leavesOf(const PageAllocator& a, const QuadtreeFit& fit) {
  std::set<std::tuple<int, int, int>> out;
  for (int i = 0; i < a.flatSize(); ++i)
    if (fit.marks[static_cast<size_t>(i)] != 0u) {
      int level, x, y;
      a.decode(i, level, x, y);
      out.insert({level, x, y});
    }
  return out;
}

TEST(QuadtreeFit, NoSampleNoPage) {
  PageAllocator a;
  a.configure(8, 16);
  const QuadtreeFit fit = fitQuadtree(a, gridOf(a, {}));
  EXPECT_EQ(fit.leaves, 0);
  EXPECT_EQ(fit.finestLevel, -1);
  EXPECT_TRUE(leavesOf(a, fit).empty());
}

TEST(QuadtreeFit, OneFineSampleSplitsItsAncestorsOnly) {
  PageAllocator a;
  a.configure(8, 16);  // levels 0 (8²) .. 3 (1)
  // One pixel in level-0 cell (5, 2) needs level 0: root -> (2,1,0) -> (1,2,1) -> (0,5,2); the
  // siblings on the way have no sample and get no page.
  const QuadtreeFit fit = fitQuadtree(a, gridOf(a, {{5, 2, 0, 7}}));
  EXPECT_EQ(leavesOf(a, fit), (std::set<std::tuple<int, int, int>>{{0, 5, 2}}));
  EXPECT_EQ(fit.marks[static_cast<size_t>(a.encode(0, 5, 2))], 7u);
  EXPECT_EQ(fit.nodesVisited, 4);
  EXPECT_EQ(fit.finestLevel, 0);
}

TEST(QuadtreeFit, ACoarseNeedStopsHigh) {
  PageAllocator a;
  a.configure(8, 16);
  // Samples needing level 2 in two cells of the same level-2 quadrant: one leaf, their pixels summed.
  const QuadtreeFit fit = fitQuadtree(a, gridOf(a, {{0, 0, 2, 3}, {3, 3, 2, 4}}));
  EXPECT_EQ(leavesOf(a, fit), (std::set<std::tuple<int, int, int>>{{2, 0, 0}}));
  EXPECT_EQ(fit.marks[static_cast<size_t>(a.encode(2, 0, 0))], 7u);
}

TEST(QuadtreeFit, AMixedNodeIsSplitForItsFinestSample) {
  PageAllocator a;
  a.configure(8, 16);
  // In quadrant (2, 0, 0): cell (0,0) needs level 0, cell (3,3) only level 2. The quadrant splits
  // to level 1; (1,1,1) holds only the coarse sample and stops there (finer than it asked for);
  // (1,0,0) splits again to the one level-0 page with the sample.
  const QuadtreeFit fit = fitQuadtree(a, gridOf(a, {{0, 0, 0, 1}, {3, 3, 2, 1}}));
  EXPECT_EQ(leavesOf(a, fit), (std::set<std::tuple<int, int, int>>{{0, 0, 0}, {1, 1, 1}}));
  EXPECT_EQ(fit.finestLevel, 0);
}

// Leaves partition the sampled cells: each sample is under exactly one leaf, at its level or finer.
TEST(QuadtreeFit, LeavesCoverEverySampleOnceAtItsLevelOrFiner) {
  PageAllocator a;
  a.configure(32, 64);
  std::vector<std::tuple<int, int, int, int>> samples;
  for (int i = 0; i < 200; ++i)  // a fixed scatter of needs: finer towards the origin
    samples.push_back({(i * 7) % 32, (i * 13) % 32, std::min(((i * 7) % 32 + (i * 13) % 32) / 10, 5), 1});
  const QuadtreeFit fit = fitQuadtree(a, gridOf(a, samples));
  for (auto [x, y, level, pixels] : samples) {
    int covering = 0;
    for (int l = 0; l < a.levels(); ++l)
      if (fit.marks[static_cast<size_t>(a.encode(l, x >> l, y >> l))] != 0u) {
        ++covering;
        EXPECT_LE(l, level) << "cell " << x << "," << y;
      }
    EXPECT_EQ(covering, 1) << "cell " << x << "," << y;
  }
}

// A map larger than the grid: a grid cell spans 2x2 level-0 pages, and a sample needing level 0
// asks for all four of them (the grid cannot say which one holds it).
TEST(QuadtreeFit, ACoarseGridAsksForTheWholeCell) {
  PageAllocator a;
  a.configure(2 * kMaxFitGrid, 16);
  ASSERT_EQ(fitGridSide(a.pagesPerSide()), kMaxFitGrid);
  const QuadtreeFit fit = fitQuadtree(a, gridOf(a, {{3, 1, 0, 1}}));
  EXPECT_EQ(leavesOf(a, fit), (std::set<std::tuple<int, int, int>>{{0, 6, 2}, {0, 7, 2}, {0, 6, 3}, {0, 7, 3}}));
}

TEST(QuadtreeFit, AGridOfTheWrongSizeIsAnError) {
  PageAllocator a;
  a.configure(8, 16);
  try {
    fitQuadtree(a, std::vector<uint32_t>(10, 0u));
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("expected 128"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sl
