// Visibility against receiver depth at the shadow-map texel under one screen pixel, for
// pre-filtered techniques: the true lit fraction of the filter box (the step, softened by what
// the box holds) and each representation's reconstruction, so ringing (Fourier) and leaking
// (Chebyshev) show at a glance. `shadowlab plot`, tour figures and the explorer's step plot
// make it here. Needs a current GL context.
#pragma once

#include "plot/plot.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace sl {

class ShaderLibrary;

struct VisibilityPlotRequest {
  std::vector<std::string> techniques;  // pre-filtered presets
  std::vector<std::string> overrides;   // "key=value" applied to every technique
  int width = 640, height = 360;        // the frame rendered to find the pixel's surface
  glm::ivec2 pixel{-1, -1};             // from the bottom left; -1: the centre
  int samples = 512;                    // receiver depths over [0, 1]
  float lo = 0.0f, hi = 1.0f;           // receiver depths shown
};

// Throws std::runtime_error with a message for the user: a technique that stores no moments, a
// pixel that shows no surface or lies outside the light's view.
Plot visibilityPlot(ShaderLibrary& shaders, const Scene& scene, const Camera& camera, const VisibilityPlotRequest& r);

}  // namespace sl
