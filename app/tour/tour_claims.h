// Checks the comparisons a tour step's caption makes ("claims", docs/tour-format.md) against the
// ray-traced reference: each viewport rendered at the step's scene, camera and light, still, its
// visibility compared with the reference's (wrong pixels, app/metrics) at each captured frame.
#pragma once

#include "gl/shader_library.h"
#include "tour/tour.h"

#include <string>
#include <vector>

namespace sl {

struct ClaimCheck {
  TourClaim claim;
  double wrongPct = 0;     // the claimed viewport's counted pixels (% of the claim's metric), last frame
  double comparedPct = 0;  // Better: viewport `than`'s at the last frame; Converges: its own at the first
  bool holds = false;      // wrongPct * factor <= comparedPct
  std::string text;        // one line saying both numbers and whether it holds
};

// Renders the step at width x height and checks each of its claims. Throws TourError for a step
// that does not load (scene, camera).
std::vector<ClaimCheck> checkStepClaims(const Tour& tour, size_t step, ShaderLibrary& shaders, int width, int height,
                                        const std::string& assetsDir);

}  // namespace sl
