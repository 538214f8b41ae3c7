// Draws a debug view's colour key (part/colour_key.h; the registry's viewColourKey finds it) over
// its image in the viewport area.
#pragma once

#include "part/colour_key.h"

#include <imgui.h>

namespace sl {

// The full key (title, gradient bar with labelled values and unit, every special colour) in a
// box at the lower left of the image, sized to the text; for an enlarged view.
void drawColourKey(ImDrawList* draw, const ColourKey& key, ImVec2 imageMin, ImVec2 imageMax);
// A thin gradient bar with its end labels along the bottom of a thumbnail; a categorical key
// as a row of its colours (the thumbnail's tooltip names them).
void drawCompactColourKey(ImDrawList* draw, const ColourKey& key, ImVec2 imageMin, ImVec2 imageMax);
// The full key as ImGui items inside a tooltip (hovering a thumbnail).
void colourKeyTooltipBody(const ColourKey& key);

}  // namespace sl
