// Internal to the scene module: mesh fix-ups the loaders share (winding, normals).
#pragma once

#include "scene/scene.h"

#include <cstddef>

namespace sl {

// True when `m` mirrors (negative determinant of its upper 3x3): it turns counter-clockwise
// triangles clockwise, so the mesh it places needs reverseWinding to keep its front faces.
bool mirrors(const glm::mat4& m);
// Swaps two corners of every triangle (front faces become back faces); normals are kept.
void reverseWinding(Mesh& mesh);

// Gives every triangle its own three vertices with the triangle's normal (flat shading).
void makeFlatNormals(Mesh& mesh);
// Makes good normals unit length and replaces zero or non-finite ones by the flat normal of
// their triangle (splitting a bad vertex that several triangles share). Returns how many
// normals were bad.
size_t repairNormals(Mesh& mesh);

}  // namespace sl
