// The left side panel: scene, cameras, viewports with their generated parameter panels,
// debug views, timings, shader errors and tools.
#pragma once

#include "explorer/explorer_state.h"
#include "gl/shader_library.h"
#include "render/renderer.h"

namespace sl {

constexpr float kSidePanelWidth = 420.0f;  // at UI scale 1
inline float sidePanelWidth(float uiScale) { return kSidePanelWidth * uiScale; }

void drawSidePanel(ExplorerState& state, Renderer& renderer, const ShaderLibrary& shaders);

}  // namespace sl
