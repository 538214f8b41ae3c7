// The light space a preset's layout computes for a scene camera, without a GPU (layout tests).
#pragma once

#include "plot/dpds.h"
#include "technique.h"

#include <algorithm>
#include <cmath>

#include <string>
#include <vector>

namespace sl::test {

inline LightSpace layoutFor(const std::string& preset, const Scene& scene, const Camera& cam,
                            std::vector<std::string> overrides = {}, float aspect = 16.0f / 9.0f) {
  Technique t = makeTechnique(preset, overrides);
  LayoutInput in;
  in.scene = &scene;
  in.cameraView = cameraView(cam);
  in.cameraProj = cameraProjection(cam, aspect);
  in.params = &t.params;
  return t.layout->compute(in);
}

// Spread of log10(texel/pixel) over a dp/ds curve's samples inside the map: 0 = perfectly even
// aliasing along the view.
inline float dpdsSpread(const DpdsCurve& c) {
  float lo = 1e30f, hi = -1e30f;
  for (float r : c.ratio)
    if (std::isfinite(r)) lo = std::min(lo, std::log10(r)), hi = std::max(hi, std::log10(r));
  return hi - lo;
}

}  // namespace sl::test
