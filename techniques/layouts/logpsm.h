// Logarithmic perspective shadow maps, after Lloyd, Govindaraju, Quammen, Molnar and Manocha
// (EGSR 2008; the survey's "perfect: logarithmic re-parameterization ... hardware support?"):
// beyond every anchor, emulated on today's rasterizer. The light's orthographic view is turned
// so that its y axis is the view direction as the light sees it (as LiSPSM's is), and y is
// warped logarithmically, u = ln(1 + t/δ) / ln(1 + 1/δ) for t in [0, 1] from the view's near
// side, so a texel grows with distance from the viewer like a pixel does (the dp/ds plot's
// "ideal logarithmic" curve). The warp bends straight edges, so casters are drawn as patches
// that tessellation shaders subdivide (passes/shadow_warp.tesc/.tese) before every vertex is
// warped; a rasterizer draws the chords between them. The chords' error is bounded (status),
// and δ is never smaller than that bound allows for the scene's longest caster edge. See
// techniques/layouts/logpsm.md for what this is and is not of the paper.
#pragma once

#include "part/part.h"

#include <memory>
#include <vector>

namespace sl {

void registerLogLayouts(std::vector<std::unique_ptr<Layout>>& out);

// Largest chord error in texels of an edge spanning `span` of the map (t units) from its near
// side, subdivided into `segments` equal pieces, for a map of `size` texels along y.
float logChordErrorTexels(float delta, float span, int segments, int size);
// The smallest δ whose worst chord (an edge of `span` from the near side, 64 segments: GL's
// largest tessellation level) stays within `maxErrorTexels`.
float logDeltaForError(float span, float maxErrorTexels, int size);

}  // namespace sl
