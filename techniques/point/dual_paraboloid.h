// Dual-paraboloid shadow map for a point light (Brabec, Annen & Seidel 2002): two views from the
// light, one per hemisphere, each mapping its hemisphere onto a disk (LightView::Projection::
// Paraboloid, layouts/dual_paraboloid.glsl). Casters are tessellated within an error budget; a
// hemisphere that holds no visible receiver is not drawn.
#pragma once

#include "point/light_faces.h"

namespace sl {

// The hemispheres' views (view 0 looks straight down, a lamp's ground in one disk; view 1 up;
// the seam, the equator, is level with the light) and which hold a visible receiver.
FaceViews paraboloidViews(const Light& light, const LayoutInput& in);

std::unique_ptr<Layout> makeDualParaboloidLayout();

}  // namespace sl
