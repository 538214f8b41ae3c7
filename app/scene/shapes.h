// Procedural meshes for the builtin scenes. All are centred on the origin in object space,
// have outward-facing counter-clockwise triangles, unit normals and uvs in [0,1].
#pragma once

#include "scene/scene.h"

namespace sl {

// Plane in the XZ plane at y = 0, normal +Y. `subdivisions` cells per side keep the
// vertices close together, so interpolated attributes stay accurate on large grounds.
Mesh makePlane(float sizeX, float sizeZ, int subdivisions);
// Axis-aligned box with separate vertices per face (hard edges).
Mesh makeBox(const glm::vec3& size);
// UV sphere: `segments` around the Y axis, segments/2 rings (at least 2).
Mesh makeSphere(float radius, int segments);
// Cylinder along Y from -height/2 to +height/2; `capped` adds the two end disks.
Mesh makeCylinder(float radius, float height, int segments, bool capped);

}  // namespace sl
