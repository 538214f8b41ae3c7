// What the point family's layouts share: under a point light a set of views (the cube's or the
// tetrahedron's faces, the paraboloids' hemispheres), of which the shadow pass draws only those
// the frame needs; under any other light one focused map. The state says how many views it drew
// ("<id>: N of M <unit> drawn") and offers the `directions` view.
#pragma once

#include "point/light_faces.h"

#include <functional>
#include <string>

namespace sl {

struct PointLayoutSpec {
  std::string id, help, glslModule;
  std::string unit;  // what its views are called in the status line: "faces", "hemispheres"
  std::vector<ParamDecl> params;
  bool fitsToPixels = true;  // declares point.fit_visible (views fitted to the pixels that read them)
  // seen: null, or the bounds of the pixels that read each view (point.fit_visible). hold: the
  // state's memory of an atlas's squares between frames (null in a stateless compute).
  std::function<FaceViews(const Light& pointLight, const LayoutInput& in, const std::vector<ViewPixelBounds>* seen,
                          AtlasHold* hold)>
      views;
};
std::unique_ptr<Layout> makePointLayout(PointLayoutSpec spec);

// The cube, the tetrahedron and the dual paraboloid.
void registerPointLayouts(std::vector<std::unique_ptr<Layout>>& out);

}  // namespace sl
