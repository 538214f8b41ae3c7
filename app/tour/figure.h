// Headless figures of tour steps for slides: each viewport's colour image and its debug views (for
// every captured frame count) in a grid whose figure comes closest to a target aspect (16:9 by
// default), text at least 1/40 of the figure's height, the step's title and caption and each
// panel's title burnt in, a colour key under heat-map views, the step's plot under the panels at
// full width; no UI chrome. Needs a current GL context (HeadlessContext).
#pragma once

#include "plot/plot.h"
#include "tour/figure_image.h"
#include "tour/tour.h"

#include <string>

namespace sl {

class ShaderLibrary;

struct FigureOptions {
  int panelWidth = 480, panelHeight = 270;  // each rendered image
  std::string assetsDir;                    // "" = defaultAssetsDir()
  float aspect = 16.0f / 9.0f;              // width / height the grid aims for
};

struct FigureResult {
  RgbaImage image;
  long long nonfinitePixels = 0;  // visibility pixels that were NaN/Inf, over every capture
  int panels = 0;                 // rendered images in the figure (placeholders not counted)
  Plot plot;                      // the step's plot, drawn under the panels (empty: the step has none)
  float bodyPixels = 0;           // the text size chosen (at least the figure's height / 40)
};

// Renders step `step` (0-based) of `tour`. A step that is not built yet gets placeholder panels
// for the missing techniques. Throws TourError (bad scene/camera) or std::runtime_error.
FigureResult renderTourFigure(const Tour& tour, size_t step, ShaderLibrary& shaders, const FigureOptions& options);

// The step's scene (assetsDir "" = defaultAssetsDir()) with the step's light direction applied,
// as figures and claim checks render it.
Scene stepSceneWithLight(const Tour& tour, size_t step, const std::string& assetsDir);

}  // namespace sl
