// A Plot (plot/plot.h) drawn into a headless figure's CPU image: a tour step's plot under its
// panels, with the same axes, ticks and legend as the SVG beside the PNG.
#pragma once

#include "plot/plot.h"
#include "tour/figure_image.h"

namespace sl {

// Draws `plot` into the w x h rectangle at (x, y) on the figure's dark background (near-black
// series are drawn white there). The legend takes the right quarter.
void drawFigurePlot(RgbaImage& img, const FigureFonts& fonts, const Plot& plot, int x, int y, int w, int h);

}  // namespace sl
