// The CPU side of a paged virtual shadow map (Lefohn et al. 2007): which virtual pages (of a mip
// pyramid of pages) the visible pixels asked for, which physical tiles of the fixed pool hold
// them, which of them must be drawn this frame and which are still valid from earlier frames.
// Pure C++ (no GL), so allocation, caching and pool exhaustion are tested without a context.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace sl {

class PageAllocator {
 public:
  // Page-table entry bits (shaders/layouts/virtual.glsl reads the same layout).
  static constexpr uint32_t kTileMask = 0xffffu;      // tile index + 1 (0: no page)
  static constexpr uint32_t kRenderedBit = 1u << 16;  // drawn this frame (a cache miss)
  static constexpr uint32_t kNeededBit = 1u << 17;    // asked for (or a fallback) this frame
  static constexpr int kLevelShift = 18;              // finestTable(): the level of the page named
  static constexpr uint32_t kLevelMask = 0x3fu;       // (6 bits, below the hits)
  static constexpr int kHitShift = 24;                // frames served from the cache, capped 255

  // pagesPerSide: pages along one side at level 0 (a power of two); levels down to one page.
  // poolTiles: physical tiles. A change of either forgets every page.
  void configure(int pagesPerSide, int poolTiles);
  void invalidate();  // something that affects the pages moved: every page must be drawn again
  // Something moved within [u0, u1] x [v0, v1] of the virtual map (uv in [0, 1]): the resident
  // pages of every level whose square touches it are dropped (drawn again when next asked for);
  // the others stay valid. Returns how many were dropped.
  int invalidateRegion(float u0, float v0, float u1, float v1);

  int pagesPerSide() const { return pages_; }
  int levels() const { return levels_; }
  int poolTiles() const { return poolTiles_; }
  // Offset of level `level` in the flat arrays (marks, page table), and their total length.
  int levelOffset(int level) const { return offsets_[static_cast<size_t>(level)]; }
  int flatSize() const { return offsets_.back(); }

  struct Frame {
    int requested = 0;        // pages the pixels asked for
    int needed = 0;           // after the fallback page and any coarsening
    int coarsened = 0;        // pages asked for that got a coarser page (pool too small; 0 = none)
    int coarsenedLevels = 0;  // levels in which any page was coarsened
    int hits = 0;             // needed pages still valid from earlier frames
    int resident = 0;         // pages in the pool after this frame
    std::vector<int> draw;    // flat page indices to draw this frame (their tile: tileOf)
    bool exhausted() const { return coarsened > 0; }
  };
  // marks: flatSize() counts of the pixels that asked for each page (0 = none). Always keeps the
  // one page of the coarsest level, so every point has a page. When the pool cannot hold every
  // request, pages of the finest level are replaced by their parent, four siblings at a time,
  // those asked for by the fewest pixels first, until the pages fit.
  Frame update(const std::vector<uint32_t>& marks);

  int tileOf(int flatIndex) const;  // -1 when not resident
  // Page table: flatSize() entries (kTileMask, bits above) for the resident pages.
  const std::vector<uint32_t>& table() const { return table_; }
  // Per page of level 0 (pagesPerSide² entries, row by row): the entry of the finest resident
  // page over it, its level in the bits at kLevelShift; 0 where no page is. What a lookup reads
  // (shaders/layouts/virtual_common.glsl): one fetch instead of a walk through the levels.
  std::vector<uint32_t> finestTable() const;
  // Level, x and y of a flat index.
  void decode(int flatIndex, int& level, int& x, int& y) const;
  int encode(int level, int x, int y) const;

 private:
  struct Resident {
    int tile = 0;
    long long lastUsed = 0;
    int hits = 0;
  };
  std::vector<int> neededSet(const std::vector<uint32_t>& marks, Frame& f) const;
  int pages_ = 0, levels_ = 0, poolTiles_ = 0;
  std::vector<int> offsets_{0};
  std::unordered_map<int, Resident> resident_;  // by flat index
  std::vector<int> freeTiles_;
  std::vector<uint32_t> table_;
  long long frame_ = 0;
};

}  // namespace sl
