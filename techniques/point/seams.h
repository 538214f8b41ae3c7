// Where a point-light layout's views meet: the cube's and tetrahedron's face edges and the
// paraboloids' equator. A point reads the view whose axis is nearest its direction from the
// light; the seam between views i and j is the plane through the light where their axes are
// equally near. What the issue asks measured apart: the error within a few texels of a seam.
#pragma once

#include "part/light_space.h"

namespace sl {

// Distance from p to the nearest seam of the view p reads, in that view's texels at p (the
// world size of a texel across the ray there). Infinite for a layout of one view.
float seamDistanceTexels(const LightSpace& space, const glm::vec3& lightPosition, const glm::vec3& p);

}  // namespace sl
