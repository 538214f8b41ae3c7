// The main area right of the side panel: 1 to 4 tiles (three in a row, four as 2x2), each with a
// technique label, the rendered image and a strip of debug-view thumbnails.
#pragma once

#include "explorer/explorer_state.h"
#include "explorer/magnifier.h"

#include <imgui.h>

#include <vector>

namespace sl {

struct ViewportTile {
  ImVec2 headerMin, headerSize;  // technique label
  ImVec2 imageMin, imageSize;    // rendered image (ImGui coordinates)
  ImVec2 thumbsMin, thumbsSize;  // debug-view thumbnails (zero height when none are selected)
};

struct MainAreaLayout {
  ImVec2 areaMin, areaSize;
  std::vector<ViewportTile> tiles;
  int renderWidth = 0, renderHeight = 0;  // image size in framebuffer pixels: what to render at
};

// Tiles the area: 1 = full, 2 or 3 = side by side, 4 = 2x2. All images get the same size because
// the renderer draws every viewport of a frame at one resolution. thumbnailsPerTile: the debug
// views shown under each image (0: none). Tall tiles (one row) with one or two views give them
// a larger share of the height, so that a slide's view is read, not guessed (#26).
MainAreaLayout layoutMainArea(ImVec2 areaMin, ImVec2 areaSize, int viewportCount, int thumbnailsPerTile,
                              ImVec2 framebufferScale);

// The share of a tile's height its thumbnails take (0 without any).
float thumbnailShare(int viewportCount, int thumbnailsPerTile);

// A big image copied straight to the window (glBlitFramebuffer) before ImGui draws on top:
// drawing it as a blended ImGui quad costs a third of the frame on a software rasterizer.
struct ScreenBlit {
  const Texture2D* texture = nullptr;
  ImVec2 min, max;  // ImGui screen coordinates (top-left origin)
};

struct MainAreaResult {
  int hoveredViewport = -1;               // image under the mouse, -1 = none
  ImVec2 hoveredTileMin, hoveredTileMax;  // its tile (image and thumbnails)
  MagnifierTarget hoveredImage;           // what the magnifier would enlarge there
  std::vector<ScreenBlit> blits;
};

// Copies the blits into the default framebuffer (call after clearing it, before ImGui renders).
void blitToScreen(const std::vector<ScreenBlit>& blits, int framebufferHeight, ImVec2 framebufferScale);

// Draws the tiles with the textures of the frame just rendered. Clicking a thumbnail shows that
// view in the big image; clicking it again goes back to the colour image.
MainAreaResult drawMainArea(const MainAreaLayout& layout, ExplorerState& state);

}  // namespace sl
