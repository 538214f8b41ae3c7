// Resolution-matched (paged virtual) shadow maps, Lefohn, Sengupta, Owens 2007: one light view
// over the whole scene at virtual.size² texels, of which only the pages the visible pixels need
// (at the mip level their footprint asks for) are rendered, each into a tile of one fixed
// physical atlas (virtual.pool²); pages stay in the atlas while nothing that affects them moved.
#pragma once

#include "part/part.h"

namespace sl {

void registerAdaptiveLayouts(std::vector<std::unique_ptr<Layout>>& out);

// The sizes a parameter set gives (pages per side a power of two, the atlas whole tiles).
struct VirtualSizes {
  int page = 128;           // texels per page side
  int pagesPerSide = 128;   // at level 0
  int virtualSize = 16384;  // pagesPerSide * page
  int poolSide = 16;        // tiles per atlas side
  int atlasSize = 2048;     // poolSide * page
};
VirtualSizes virtualSizes(const ParamSet& params);

}  // namespace sl
