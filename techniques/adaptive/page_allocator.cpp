#include "adaptive/page_allocator.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

namespace sl {

void PageAllocator::configure(int pagesPerSide, int poolTiles) {
  if (pagesPerSide < 1 || (pagesPerSide & (pagesPerSide - 1)) != 0 || pagesPerSide > 4096)
    throw std::invalid_argument("virtual shadow map: pages per side must be a power of two up to 4096, got " +
                                std::to_string(pagesPerSide));
  if (poolTiles < 1 || poolTiles > static_cast<int>(kTileMask) - 1)
    throw std::invalid_argument("virtual shadow map: the pool must hold 1 to 65534 tiles, got " +
                                std::to_string(poolTiles));
  if (pagesPerSide == pages_ && poolTiles == poolTiles_) return;
  pages_ = pagesPerSide;
  poolTiles_ = poolTiles;
  levels_ = 0;
  offsets_ = {0};
  for (int n = pages_; n >= 1; n /= 2) {
    offsets_.push_back(offsets_.back() + n * n);
    ++levels_;
  }
  table_.assign(static_cast<size_t>(flatSize()), 0u);
  invalidate();
}

void PageAllocator::invalidate() {
  resident_.clear();
  freeTiles_.clear();
  // Lowest tile first: a small scene fills the atlas from its origin (easier to read in views).
  for (int t = poolTiles_ - 1; t >= 0; --t) freeTiles_.push_back(t);
  std::fill(table_.begin(), table_.end(), 0u);
}

int PageAllocator::invalidateRegion(float u0, float v0, float u1, float v1) {
  if (!(u0 <= u1 && v0 <= v1)) return 0;  // empty (or NaN) region: nothing can have changed
  std::vector<int> dropped;
  for (const auto& [index, r] : resident_) {
    int level, x, y;
    decode(index, level, x, y);
    const float n = static_cast<float>(pages_ >> level);
    // Closed intervals: a region ending exactly on a page border still touches that page.
    if (x / n <= u1 && (x + 1) / n >= u0 && y / n <= v1 && (y + 1) / n >= v0) dropped.push_back(index);
  }
  for (int index : dropped) {
    freeTiles_.push_back(resident_[index].tile);
    resident_.erase(index);
    table_[static_cast<size_t>(index)] = 0u;
  }
  return static_cast<int>(dropped.size());
}

void PageAllocator::decode(int flatIndex, int& level, int& x, int& y) const {
  level = static_cast<int>(std::upper_bound(offsets_.begin(), offsets_.end(), flatIndex) - offsets_.begin()) - 1;
  const int n = pages_ >> level, local = flatIndex - offsets_[static_cast<size_t>(level)];
  x = local % n;
  y = local / n;
}

int PageAllocator::encode(int level, int x, int y) const {
  return offsets_[static_cast<size_t>(level)] + y * (pages_ >> level) + x;
}

// From the coarsest level down: a page's finest resident page is itself when it is resident,
// else its parent's. One visit per page of every level (4/3 of level 0's), whatever the levels.
std::vector<uint32_t> PageAllocator::finestTable() const {
  std::vector<uint32_t> coarser;  // the level above's answers
  for (int m = levels_ - 1; m >= 0; --m) {
    const size_t n = static_cast<size_t>(pages_ >> m);
    std::vector<uint32_t> finest(n * n, 0u);
    for (size_t y = 0; y < n; ++y)
      for (size_t x = 0; x < n; ++x) {
        const uint32_t e = table_[static_cast<size_t>(encode(m, static_cast<int>(x), static_cast<int>(y)))];
        if ((e & kTileMask) != 0u)
          finest[y * n + x] = e | (static_cast<uint32_t>(m) << kLevelShift);
        else if (!coarser.empty())
          finest[y * n + x] = coarser[(y >> 1) * (n >> 1) + (x >> 1)];
      }
    coarser = std::move(finest);
  }
  return coarser;
}

int PageAllocator::tileOf(int flatIndex) const {
  auto it = resident_.find(flatIndex);
  return it == resident_.end() ? -1 : it->second.tile;
}

// The requested pages and the coarsest page; then, while the pool is too small, sibling groups
// of the finest level still present become their parent, the groups fewest pixels asked for
// first (the parent inherits their pixels, so a level coarsened next weighs them too).
std::vector<int> PageAllocator::neededSet(const std::vector<uint32_t>& marks, Frame& f) const {
  std::vector<std::map<int, uint64_t>> byLevel(static_cast<size_t>(levels_));  // page -> pixels
  for (int i = 0; i < flatSize(); ++i) {
    if (marks[static_cast<size_t>(i)] == 0u) continue;
    int level, x, y;
    decode(i, level, x, y);
    byLevel[static_cast<size_t>(level)][i] += marks[static_cast<size_t>(i)];
    ++f.requested;
  }
  byLevel.back() = {{encode(levels_ - 1, 0, 0), 1}};
  size_t total = 0;
  for (const auto& l : byLevel) total += l.size();
  for (int level = 0; level < levels_ - 1 && total > static_cast<size_t>(poolTiles_); ++level) {
    auto& pages = byLevel[static_cast<size_t>(level)];
    auto& parents = byLevel[static_cast<size_t>(level + 1)];
    std::map<int, std::pair<uint64_t, std::vector<int>>> groups;  // parent -> pixels, children
    for (const auto& [i, pixels] : pages) {
      int l, x, y;
      decode(i, l, x, y);
      auto& g = groups[encode(level + 1, x / 2, y / 2)];
      g.first += pixels;
      g.second.push_back(i);
    }
    std::vector<std::pair<uint64_t, int>> order;
    for (const auto& [parent, g] : groups) order.push_back({g.first, parent});
    std::sort(order.begin(), order.end());
    for (const auto& [pixels, parent] : order) {
      if (total <= static_cast<size_t>(poolTiles_)) break;
      const auto& children = groups[parent].second;
      total -= children.size();
      for (int c : children) pages.erase(c);
      f.coarsened += static_cast<int>(children.size());
      if (!parents.count(parent)) ++total;
      parents[parent] += pixels;
    }
    ++f.coarsenedLevels;
  }
  std::vector<int> needed;
  // Coarse pages first: if the pool is smaller than even the coarse levels, these survive.
  for (int level = levels_ - 1; level >= 0; --level)
    for (const auto& [i, pixels] : byLevel[static_cast<size_t>(level)]) needed.push_back(i);
  if (needed.size() > static_cast<size_t>(poolTiles_)) needed.resize(static_cast<size_t>(poolTiles_));
  return needed;
}

PageAllocator::Frame PageAllocator::update(const std::vector<uint32_t>& marks) {
  if (marks.size() != static_cast<size_t>(flatSize()))
    throw std::invalid_argument("virtual shadow map: " + std::to_string(marks.size()) + " page marks for " +
                                std::to_string(flatSize()) + " pages");
  ++frame_;
  Frame f;
  const std::vector<int> needed = neededSet(marks, f);
  f.needed = static_cast<int>(needed.size());
  std::vector<int> missing;
  for (int i : needed) {
    auto it = resident_.find(i);
    if (it == resident_.end()) {
      missing.push_back(i);
      continue;
    }
    it->second.lastUsed = frame_;
    ++it->second.hits;
    ++f.hits;
  }
  // Tiles for the missing pages: free ones, then the least recently used pages not needed now.
  std::vector<std::pair<long long, int>> evictable;
  for (const auto& [index, r] : resident_)
    if (r.lastUsed != frame_) evictable.push_back({r.lastUsed, index});
  std::sort(evictable.begin(), evictable.end());
  size_t nextEvict = 0;
  for (int i : missing) {
    int tile;
    if (!freeTiles_.empty()) {
      tile = freeTiles_.back();
      freeTiles_.pop_back();
    } else {
      const int victim = evictable.at(nextEvict++).second;  // needed <= pool, so there is one
      tile = resident_[victim].tile;
      resident_.erase(victim);
    }
    resident_[i] = Resident{tile, frame_, 0};
    f.draw.push_back(i);
  }
  f.resident = static_cast<int>(resident_.size());
  std::fill(table_.begin(), table_.end(), 0u);
  for (const auto& [index, r] : resident_) {
    uint32_t e = static_cast<uint32_t>(r.tile + 1) | (static_cast<uint32_t>(std::min(r.hits, 255)) << kHitShift);
    if (r.lastUsed == frame_) e |= kNeededBit;
    table_[static_cast<size_t>(index)] = e;
  }
  for (int i : f.draw) table_[static_cast<size_t>(i)] |= kRenderedBit;
  return f;
}

}  // namespace sl
