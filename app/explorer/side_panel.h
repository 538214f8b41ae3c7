// The left side panel: scene, cameras, viewports with their generated parameter panels,
// debug views, timings, shader errors and tools.
#pragma once

#include "explorer/explorer_state.h"
#include "gl/shader_library.h"
#include "render/renderer.h"

namespace sl {

constexpr float kSidePanelWidth = 420.0f;  // at UI scale 1
// Grows with the UI scale, but leaves the viewports at least 60 % of the window.
inline float sidePanelWidth(float uiScale, float displayWidth) {
  const float scaled = kSidePanelWidth * uiScale;
  return scaled < displayWidth * 0.4f ? scaled
                                      : (kSidePanelWidth < displayWidth * 0.4f ? displayWidth * 0.4f : kSidePanelWidth);
}

void drawSidePanel(ExplorerState& state, Renderer& renderer, const ShaderLibrary& shaders);

}  // namespace sl
