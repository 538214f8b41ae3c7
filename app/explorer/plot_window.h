// Plots in the explorer: a tour step's plot (computed when the step is shown) and the live dp/ds
// panel (perspective aliasing along the view for the shown viewports' layouts with their current
// parameters, next to uniform, PSM, LiSPSM, cascades and the ideal logarithmic curve). Both use
// the Plot description that figures and SVG files use (plot/plot.h).
#pragma once

#include "explorer/explorer_state.h"
#include "plot/plot.h"

#include <imgui.h>

#include <string>
#include <vector>

namespace sl {

// Draws `plot` at the cursor of the current window, `size` pixels including the legend.
void drawPlotWidget(const Plot& plot, ImVec2 size);

// Where legend entries of these widths go in rows `lineHeight` apart within `width` pixels: left
// to right, wrapping before an entry that would pass the edge (an entry wider than the whole
// width gets a row of its own). Offsets from the legend's top-left corner.
std::vector<ImVec2> flowLegend(const std::vector<float>& entryWidths, float width, float lineHeight);

// Dimmed text wrapped to `width` (a plot's axis labels and notes) under the widget.
void drawPlotCaption(const std::string& text, float width);

// The dp/ds curves of the shown viewports (labelled "1: lispsm", ...) and the reference layouts
// not shown, for the current camera and a render of width x height.
Plot liveDpdsPlot(const ExplorerState& state, int width, int height);

// The window of state.showDpdsPlot, near the top right of the main area.
void drawDpdsWindow(ExplorerState& state, int renderWidth, int renderHeight, ImVec2 areaMin, ImVec2 areaSize);

}  // namespace sl
