// Perspective aliasing along the view direction (the survey's error-analysis slides): for
// receivers on the camera's centre ray at view depth z, the world size of one shadow-map texel
// (along the view direction as the light sees it: projected onto the light's plane) over the
// world size of one pixel there. 1 = a texel per pixel; above 1 the map undersamples. The ideal
// logarithmic parametrization with the same texels per side is flat.
#pragma once

#include "plot/plot.h"
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

// The same for techniques already made (the explorer's viewports with their current parameters),
// each with the label its curve gets.
struct LabelledTechnique {
  std::string label;
  const Technique* technique = nullptr;
};
std::vector<DpdsCurve> dpdsCurves(const Scene& scene, const Camera& cam, int width, int height,
                                  const std::vector<LabelledTechnique>& techniques, int samples = 64);

// The curves as a log-log plot (view depth vs texel/pixel size); plotSvg draws it as a file.
Plot dpdsPlot(const std::vector<DpdsCurve>& curves, const std::string& title);

}  // namespace sl
