// Hold V over a viewport whose representation has a visibility curve (RepresentationState::
// visibilityCurve): a window next to the mouse plots it at the shadow-map texel under the mouse
// with its truth, and the curves of every other shown viewport on the same axis at the same
// surface point. Pre-filtered maps: visibility against receiver depth, the truth the lit
// fraction of the filter box (VSM, Gaussian, EWGF, Fourier, MSM side by side: leaking and ringing
// at a glance; the headless twin is `shadowlab plot`). Deep shadow maps: transmittance against
// light depth, the truth the reference traced along the texel's light ray.
#pragma once

#include "explorer/magnifier.h"
#include "render/renderer.h"

#include <vector>

namespace sl {

// `target` is the hovered image of shown[hovered] (its size is the rendered frame's); the
// renderer must hold this frame's G-buffer. Draws nothing for a representation without a curve.
void drawVisibilityPlot(ShaderLibrary& shaders, const Renderer& renderer, const std::vector<Viewport*>& shown,
                        size_t hovered, const MagnifierTarget& target, ImVec2 mouse);

}  // namespace sl
