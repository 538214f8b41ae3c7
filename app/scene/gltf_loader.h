// Internal to the scene module: appends the triangles of a glTF 2.0 file to a Scene.
#pragma once

#include "scene/scene.h"

#include <string>

namespace sl {

// Loads `path` (.gltf or .glb) and appends its meshes, materials, textures and one instance per
// drawn primitive; each instance's transform is `modelTransform * nodeWorldMatrix`.
// Throws SceneError whose message starts with `path`.
void appendGltf(Scene& scene, const std::string& path, const glm::mat4& modelTransform);

}  // namespace sl
