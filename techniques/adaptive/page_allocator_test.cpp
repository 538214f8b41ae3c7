// The allocation of a paged virtual shadow map: caching, eviction, pool exhaustion.
#include "adaptive/page_allocator.h"

#include <gtest/gtest.h>

#include <set>

namespace sl {
namespace {

std::vector<uint32_t> marksOf(const PageAllocator& a, const std::vector<int>& pages) {
  std::vector<uint32_t> m(static_cast<size_t>(a.flatSize()), 0u);
  for (int i : pages) m[static_cast<size_t>(i)] = 1u;
  return m;
}

TEST(PageAllocator, LevelsDownToOnePage) {
  PageAllocator a;
  a.configure(8, 16);
  EXPECT_EQ(a.levels(), 4);  // 8², 4², 2², 1
  EXPECT_EQ(a.flatSize(), 64 + 16 + 4 + 1);
  int level, x, y;
  a.decode(a.encode(2, 1, 0), level, x, y);
  EXPECT_EQ(level, 2);
  EXPECT_EQ(x, 1);
  EXPECT_EQ(y, 0);
  EXPECT_THROW(a.configure(6, 16), std::invalid_argument);
  EXPECT_THROW(a.configure(8, 0), std::invalid_argument);
}

TEST(PageAllocator, DrawsMissesOnceThenHitsTheCache) {
  PageAllocator a;
  a.configure(8, 16);
  const std::vector<int> asked = {a.encode(0, 1, 1), a.encode(0, 2, 1), a.encode(1, 3, 3)};
  PageAllocator::Frame f = a.update(marksOf(a, asked));
  EXPECT_EQ(f.requested, 3);
  EXPECT_EQ(f.needed, 4);  // and the coarsest page
  EXPECT_EQ(f.draw.size(), 4u);
  EXPECT_EQ(f.hits, 0);
  std::set<int> tiles;
  for (int i : f.draw) tiles.insert(a.tileOf(i));
  EXPECT_EQ(tiles.size(), 4u);  // distinct tiles
  for (int i : asked) EXPECT_NE(a.table()[static_cast<size_t>(i)] & PageAllocator::kRenderedBit, 0u);

  f = a.update(marksOf(a, asked));
  EXPECT_TRUE(f.draw.empty());
  EXPECT_EQ(f.hits, 4);
  for (int i : asked) {
    const uint32_t e = a.table()[static_cast<size_t>(i)];
    EXPECT_EQ(e & PageAllocator::kRenderedBit, 0u);
    EXPECT_EQ(e >> PageAllocator::kHitShift, 1u);
  }
  a.invalidate();
  f = a.update(marksOf(a, asked));
  EXPECT_EQ(f.draw.size(), 4u);
}

// The finest resident page over each level-0 page, worked by hand on 8² pages: (1, 1) and
// (2, 1) of level 0, (3, 3) of level 1 (level-0 pages 6..7 x 6..7) and the one page of level 3.
TEST(PageAllocator, FinestTableNamesTheFinestResidentPageAndItsLevel) {
  PageAllocator a;
  a.configure(8, 16);
  a.update(marksOf(a, {a.encode(0, 1, 1), a.encode(0, 2, 1), a.encode(1, 3, 3)}));
  const std::vector<uint32_t> finest = a.finestTable();
  ASSERT_EQ(finest.size(), 64u);
  auto at = [&](int x, int y) { return finest[static_cast<size_t>(y * 8 + x)]; };
  auto levelOf = [](uint32_t e) { return int((e >> PageAllocator::kLevelShift) & PageAllocator::kLevelMask); };
  auto tileOf = [](uint32_t e) { return int(e & PageAllocator::kTileMask) - 1; };
  EXPECT_EQ(levelOf(at(1, 1)), 0);
  EXPECT_EQ(tileOf(at(1, 1)), a.tileOf(a.encode(0, 1, 1)));
  EXPECT_EQ(tileOf(at(2, 1)), a.tileOf(a.encode(0, 2, 1)));
  for (int y = 6; y < 8; ++y)
    for (int x = 6; x < 8; ++x) {
      EXPECT_EQ(levelOf(at(x, y)), 1);
      EXPECT_EQ(tileOf(at(x, y)), a.tileOf(a.encode(1, 3, 3)));
    }
  // Everywhere else the coarsest page (level 3), with the entry's own bits kept.
  EXPECT_EQ(levelOf(at(0, 0)), 3);
  EXPECT_EQ(tileOf(at(5, 7)), a.tileOf(a.encode(3, 0, 0)));
  EXPECT_NE(at(0, 0) & PageAllocator::kRenderedBit, 0u);
  // Before any allocation no page is resident: 0 everywhere.
  PageAllocator empty;
  empty.configure(8, 16);
  for (uint32_t e : empty.finestTable()) EXPECT_EQ(e, 0u);
}

TEST(PageAllocator, EvictsTheLeastRecentlyUsedPage) {
  PageAllocator a;
  a.configure(8, 3);  // the coarsest page and two more
  const int p = a.encode(0, 0, 0), q = a.encode(0, 1, 0), r = a.encode(0, 2, 0);
  a.update(marksOf(a, {p}));
  a.update(marksOf(a, {q}));  // p kept (a free tile remained)
  EXPECT_GE(a.tileOf(p), 0);
  a.update(marksOf(a, {q, r}));  // no free tile: p, unused the longest, goes
  EXPECT_EQ(a.tileOf(p), -1);
  EXPECT_GE(a.tileOf(q), 0);
  EXPECT_GE(a.tileOf(r), 0);
}

TEST(PageAllocator, ExhaustedPoolFallsBackToCoarserPages) {
  PageAllocator a;
  a.configure(8, 5);
  std::vector<int> all;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) all.push_back(a.encode(0, x, y));
  PageAllocator::Frame f = a.update(marksOf(a, all));
  EXPECT_EQ(f.requested, 64);
  EXPECT_TRUE(f.exhausted());
  EXPECT_EQ(f.coarsenedLevels, 2);  // 64 -> 16 -> 4 pages of level 2, + the coarsest = 5
  EXPECT_EQ(f.needed, 5);
  for (int x = 0; x < 2; ++x)
    for (int y = 0; y < 2; ++y) EXPECT_GE(a.tileOf(a.encode(2, x, y)), 0);
  EXPECT_EQ(a.tileOf(all.front()), -1);
  // Smaller than even that: the coarse pages come first, the one page of the top level always.
  a.configure(8, 1);
  f = a.update(marksOf(a, all));
  EXPECT_EQ(f.needed, 1);
  EXPECT_GE(a.tileOf(a.encode(3, 0, 0)), 0);
}

TEST(PageAllocator, CoarsensOnlyAsManyPagesAsNeededFewestPixelsFirst) {
  PageAllocator a;
  a.configure(8, 6);
  std::vector<uint32_t> marks(static_cast<size_t>(a.flatSize()), 0u);
  std::vector<int> busy, quiet;  // two sibling groups of level 0: many pixels, few
  for (int k = 0; k < 4; ++k) {
    busy.push_back(a.encode(0, k & 1, k >> 1));
    quiet.push_back(a.encode(0, 4 + (k & 1), 4 + (k >> 1)));
  }
  for (int i : busy) marks[static_cast<size_t>(i)] = 500u;
  for (int i : quiet) marks[static_cast<size_t>(i)] = 3u;
  PageAllocator::Frame f = a.update(marks);  // 8 + the coarsest page > 6: one group goes up
  EXPECT_TRUE(f.exhausted());
  EXPECT_EQ(f.coarsened, 4);
  EXPECT_EQ(f.coarsenedLevels, 1);
  EXPECT_EQ(f.needed, 6);
  for (int i : busy) EXPECT_GE(a.tileOf(i), 0);
  for (int i : quiet) EXPECT_EQ(a.tileOf(i), -1);
  EXPECT_GE(a.tileOf(a.encode(1, 2, 2)), 0);  // the quiet group's parent
}

TEST(PageAllocator, RejectsMarksOfAnotherSize) {
  PageAllocator a;
  a.configure(4, 4);
  EXPECT_THROW(a.update(std::vector<uint32_t>(3, 1u)), std::invalid_argument);
}

// Objects moving over part of the map drop only the pages (of every level) under them.
TEST(PageAllocator, InvalidatingARegionDropsOnlyThePagesUnderIt) {
  PageAllocator a;
  a.configure(8, 16);
  const std::vector<int> asked = {a.encode(0, 0, 0), a.encode(0, 7, 7), a.encode(1, 3, 0), a.encode(2, 1, 1)};
  a.update(marksOf(a, asked));
  // uv [0.9, 1] x [0.9, 1]: level-0 page (7,7), level-2 page (1,1) and the coarsest page.
  EXPECT_EQ(a.invalidateRegion(0.9f, 0.9f, 1.0f, 1.0f), 3);
  EXPECT_EQ(a.tileOf(a.encode(0, 7, 7)), -1);
  EXPECT_EQ(a.tileOf(a.encode(2, 1, 1)), -1);
  EXPECT_EQ(a.tileOf(a.encode(a.levels() - 1, 0, 0)), -1);
  EXPECT_GE(a.tileOf(a.encode(0, 0, 0)), 0);
  EXPECT_GE(a.tileOf(a.encode(1, 3, 0)), 0);
  const PageAllocator::Frame f = a.update(marksOf(a, asked));
  EXPECT_EQ(f.hits, 2);
  EXPECT_EQ(f.draw.size(), 3u);  // drawn again, into the tiles freed
  EXPECT_EQ(f.resident, 5);
  EXPECT_EQ(a.invalidateRegion(0.5f, 0.5f, 0.4f, 0.6f), 0);  // empty region
}

}  // namespace
}  // namespace sl
