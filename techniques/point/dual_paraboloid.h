// Dual-paraboloid shadow map for a point light (Brabec, Annen & Seidel 2002): two views from the
// light, one per hemisphere, each mapping its hemisphere onto a disk (LightView::Projection::
// Paraboloid, layouts/dual_paraboloid.glsl). Casters are tessellated within an error budget; a
// hemisphere that holds no visible receiver is not drawn.
#pragma once

#include "point/light_faces.h"

namespace sl {

// The hemispheres' views (view 0 looks straight down, a lamp's ground in one disk; view 1 up;
// the seam, the equator, is level with the light) and which hold a visible receiver.
// With paraboloid.fit on, each drawn hemisphere's window is fitted to the directions of its visible
// receivers (fitParaboloidWindow); off, or where they cannot be bounded, the whole disk.
// With `seen` (point.fit_visible) a hemisphere is needed when a visible pixel reads it and its
// window holds those pixels' images (paraboloidWindowAround) instead.
FaceViews paraboloidViews(const Light& light, const LayoutInput& in,
                          const std::vector<ViewPixelBounds>* seen = nullptr);

// The window (LightView::paraboloidWindow: centre, zoom) of a size-texel paraboloid map that holds
// the images of the directions `dirs` (unit vectors in the view's frame, the hemisphere's axis -z)
// with a margin of 5 % and 4 texels on each side, for filter taps and the snapping. Beyond the
// paper (Brabec et al. draw the whole hemisphere): the survey's focusing applied to a paraboloid.
// Everything between the directions on the sphere is bounded by great-circle arcs between pairs
// of them, whose images are circle arcs (the map is the stereographic projection of the
// directions): the window is the square around those images, cut to the disk's, when the
// directions lie in one closed hemisphere (the drawn one, or within 89 degrees of their mean);
// (0, 0, 1, 1), the whole disk, when there are none, they do not, or two are opposite. snap: the zoom on a ladder of
// quarter octaves and the centre on whole texels, so the texel grid stands still while the camera moves within a step.
glm::vec4 fitParaboloidWindow(const std::vector<glm::vec3>& dirs, int size, bool snap);
// The window around the box [lo, hi] of images on the whole disk (paraboloidDiskImage), with the
// same margins and snapping, cut to the disk's square; the whole disk along an axis where it
// would magnify by less than 1, and where the box is empty. square: one zoom for both axes, from
// the longer side (fitParaboloidWindow); else each axis its own (point.fit_visible).
glm::vec4 paraboloidWindowAround(glm::vec2 lo, glm::vec2 hi, int size, bool snap, bool square);

std::unique_ptr<Layout> makeDualParaboloidLayout();

}  // namespace sl
