// Fitting a point light's views to the pixels the camera sees in them (point.fit_visible;
// sample-distribution fitting, Lauritzen, Salvi & Lefohn 2011, applied per face: beyond the
// papers). The frustum fit bounds a face by view frustum ∩ scene bounds ∩ its region, which is
// most of the face when the camera sees the lamp; a GPU min/max reduction of the G-buffer's
// positions in each view gives what is really there. It runs before the shadow pass and the
// frame's fit waits for it (no latency: the views are refitted in the same frame).
#pragma once

#include "part/part.h"

#include <memory>
#include <vector>

namespace sl {

// The visible pixels of one view: their image coordinates (a face's tangent coordinates x/-z,
// y/-z in its view; a paraboloid's whole-disk image) and distances (a face's -z, a paraboloid's
// radial distance). valid false: no visible pixel reads this view.
struct ViewPixelBounds {
  bool valid = false;
  glm::vec2 lo{0.0f}, hi{0.0f};
  float nearest = 0.0f, farthest = 0.0f;
};

// The declaration of point.fit_visible.
ParamDecl fitVisibleParam();

// The world points a face's fit is cropped to: the corners of the pixels' tangent rectangle in
// `view`, padded by 2 % and 4 texels of a size-texel map on each side, at their nearest and
// farthest distances (fitPerspective crops to their projection without a margin).
std::vector<glm::vec3> pixelBoundsCorners(const ViewPixelBounds& b, const glm::mat4& view, int size);

// The GPU side: one reduction over the G-buffer into a buffer read back at once.
class ViewPixelReduction {
 public:
  ViewPixelReduction();
  ~ViewPixelReduction();
  // The bounds of every view of `space` (at most 6; paraboloid: the views are hemispheres);
  // empty when the pass's program does not build.
  std::vector<ViewPixelBounds> reduce(const PartContext& ctx, const LightSpace& space, const Light& light);

 private:
  unsigned buffer_ = 0;
};

}  // namespace sl
