// The plot a tour step names ("plot" in docs/tour-format.md), made on the step's scene and
// camera the way `shadowlab plot` makes it. Figures draw it under their panels and write it as
// an SVG beside the PNG; the explorer shows it in a window while the step is on screen.
#pragma once

#include "plot/plot.h"
#include "tour/tour.h"

namespace sl {

class ShaderLibrary;

// The legend name of a dp/ds plot's technique "preset[:key=v;key=v]" in step `s`: the title of
// the viewport with that preset and exactly those overrides when there is one (the legend then
// names what the caption and the panels name), else "preset (key=v, key=v)".
std::string stepSeriesLabel(const TourStep& s, const std::string& spec);

// An empty Plot for a step without one. A visibility plot renders (needs a current GL context);
// throws std::runtime_error naming the step when the plot cannot be made (the pixel shows no
// surface, say).
Plot stepPlot(const Tour& tour, size_t step, const Scene& scene, const Camera& camera, ShaderLibrary& shaders,
              int width, int height);

}  // namespace sl
