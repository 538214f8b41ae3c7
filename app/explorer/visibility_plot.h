// Hold V over a viewport of a pre-filtered technique: a window next to the mouse plots visibility
// against receiver depth at the shadow-map texel under the mouse: the true lit fraction of the
// hovered viewport's filter box, its reconstruction, and the reconstructions of every other
// shown pre-filtered viewport at the same surface point (VSM, Gaussian, EWGF, Fourier, MSM side
// by side: leaking and ringing at a glance; the headless twin is `shadowlab plot`). Over a deep
// shadow map it plots the stored transmittance of the deep texel against light depth over the
// reference's along that texel's light ray (techniques/deep/deep_curve.h).
#pragma once

#include "explorer/magnifier.h"
#include "render/renderer.h"

#include <vector>

namespace sl {

// `target` is the hovered image of shown[hovered] (its size is the rendered frame's); the
// renderer must hold this frame's G-buffer. Draws nothing for a technique that stores no moments.
void drawVisibilityPlot(ShaderLibrary& shaders, const Renderer& renderer, const std::vector<Viewport*>& shown,
                        size_t hovered, const MagnifierTarget& target, ImVec2 mouse);

}  // namespace sl
