// Debug views of the moment maps, drawn as passes after the filter: `moments` (one stored
// channel, selected by view.channel), `variance` (sigma^2 per texel on a log colour scale with
// its key), `fourier` (one basis image of the convolution representation, signed colour map),
// and for the soft ones `blocker-depth` and `penumbra` (their blocker estimate per pixel).
#pragma once

#include "part/part.h"

namespace sl {

class FrameGraph;

// The views this representation can draw (has a variance: two-moment and four-moment ones).
std::vector<std::string> momentViewNames(bool hasVariance, bool fourier, bool soft);
// Adds a pass for each of `names` that the viewport shows, reading `moments`.
void addMomentViewPasses(FrameGraph& graph, const PartContext& ctx, const std::string& moments,
                         const std::vector<std::string>& names);

}  // namespace sl
