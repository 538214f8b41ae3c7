// Perspective aliasing along the view direction (the survey's error-analysis slides): for
// receivers on the camera's centre ray at view depth z, the world size of one shadow-map texel
// (along the view direction as the light sees it: projected onto the light's plane) over the
// world size of one pixel there. 1 = a texel per pixel; above 1 the map undersamples. The ideal
// logarithmic parametrization with the same texels per side is flat.
#pragma once

#include "technique.h"

#include <string>
#include <vector>

namespace sl {

struct DpdsCurve {
  std::string label;
  std::vector<float> depth, ratio;  // view depth z, texel size / pixel size (NaN where not in the map)
};

// One curve per technique ("preset" or "preset:key=value,key=value"), `samples` depths spread
// logarithmically over the camera's near plane to the farthest visible point of the scene, plus
// "ideal logarithmic" for the first technique's texels per side.
std::vector<DpdsCurve> dpdsCurves(const Scene& scene, const Camera& cam, int width, int height,
                                  const std::vector<std::string>& techniques, int samples = 64);

// A log-log SVG plot of the curves (view depth vs texel/pixel size).
std::string dpdsSvg(const std::vector<DpdsCurve>& curves, const std::string& title);

}  // namespace sl
