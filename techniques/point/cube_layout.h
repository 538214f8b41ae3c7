// Cube shadow map for a point light: six 90-degree faces, each a perspective light view, each
// fitted to what the camera sees through it (the survey's "focus the shadow map" per face), and
// a face that holds no visible receiver is not drawn.
#pragma once

#include "part/part.h"

#include <array>
#include <memory>
#include <vector>

namespace sl {

// The six faces in the order of the layers: +X, -X, +Y, -Y, +Z, -Z.
struct CubeFace {
  glm::vec3 axis, up;
};
const std::array<CubeFace, 6>& cubeFaces();

// The cube's views for the light (a point light at `light.position`) and which faces hold a
// visible receiver (view frustum ∩ scene bounds ∩ the face's pyramid). Every face has a view;
// an undrawn face's is its uncropped pyramid.
struct CubeViews {
  LightSpace space;
  std::array<bool, 6> needed{};
  int neededCount() const;
};
CubeViews cubeViews(const Light& light, const LayoutInput& in);

void registerPointLayouts(std::vector<std::unique_ptr<Layout>>& out);

}  // namespace sl
