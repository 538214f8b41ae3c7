// Fitted virtual shadow maps (Giegl & Wimmer, Graphics Interface 2007), the CPU half: the GPU
// samples the scene from the eye and writes, per cell of a grid over the light's view, the
// finest page level a visible pixel there needs; this turns that grid into a quadtree (the
// paper's "hierarchical grid ... traversed in kd-tree fashion") whose leaves are the pages to
// draw. A node is split into its four children while a sample under it needs a finer level;
// children without samples are dropped. The leaves partition the sampled area: each sample is
// covered by exactly one page, at its level or finer (a node that mixes needs is split for the
// finest, so its coarse-needing corners get finer pages than they asked for). The survey's
// summary: "FVSM: CPU, RMSM: GPU"; the resolution-matched criterion marks pages on the GPU.
#pragma once

#include "adaptive/page_allocator.h"

#include <cstdint>
#include <vector>

namespace sl {

// Cells per side of the fit grid for a map of `pagesPerSide` level-0 pages: one cell per level-0
// page, at most kMaxFitGrid (then a cell spans several level-0 pages and a sample needing a
// level finer than the cell asks for all of the cell at that level).
constexpr int kMaxFitGrid = 512;
int fitGridSide(int pagesPerSide);

// The grid as the marking pass writes it (passes/virtual_mark.comp), 2 * G² uints for
// G = fitGridSide(): [0, G²) per cell `levels - needed level` (0: no sample there; the larger,
// the finer), then [G², 2 G²) the pixels that fell in the cell.
struct QuadtreeFit {
  std::vector<uint32_t> marks;  // PageAllocator::flatSize(): pixels under each leaf page, 0 elsewhere
  int leaves = 0;               // pages to draw (before the allocator adds the coarsest)
  int nodesVisited = 0;         // nodes of the traversal, leaves and splits
  int finestLevel = -1;         // finest leaf level (-1: no sample)
};
// Throws std::invalid_argument (naming the expected size) when the grid does not fit `pages`.
QuadtreeFit fitQuadtree(const PageAllocator& pages, const std::vector<uint32_t>& grid);

}  // namespace sl
