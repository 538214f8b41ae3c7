// Hold V over a viewport of a pre-filtered technique: a window next to the mouse plots its
// reconstructed visibility against receiver depth at the shadow-map texel under the mouse, over
// the true lit fraction of the filter box (the headless twin is `shadowlab plot`). Over a deep
// shadow map it plots the stored transmittance of the deep texel against light depth over the
// reference's along that texel's light ray (techniques/deep/deep_curve.h).
#pragma once

#include "explorer/magnifier.h"
#include "render/renderer.h"

namespace sl {

// `target` is the hovered image of `vp` (its size is the rendered frame's); the renderer must
// hold this frame's G-buffer. Draws nothing for a technique that stores no moments.
void drawVisibilityPlot(ShaderLibrary& shaders, const Renderer& renderer, const Viewport& vp,
                        const MagnifierTarget& target, ImVec2 mouse);

}  // namespace sl
