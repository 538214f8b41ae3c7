#include "scene/scene_effects.h"

namespace sl {

bool instanceSemiTransparent(const Scene& scene, size_t index) {
  if (index >= scene.instances.size()) return false;
  const int mesh = scene.instances[index].mesh;
  if (mesh < 0 || static_cast<size_t>(mesh) >= scene.meshes.size()) return false;
  const int material = scene.meshes[static_cast<size_t>(mesh)].material;
  if (material < 0 || static_cast<size_t>(material) >= scene.materials.size()) return false;
  return scene.materials[static_cast<size_t>(material)].alphaBlend;
}

SceneEffects sceneEffects(const Scene& scene) {
  SceneEffects e;
  e.semiTransparent = !scene.volumes.empty();
  for (size_t i = 0; i < scene.instances.size() && !e.semiTransparent; ++i)
    e.semiTransparent = instanceSemiTransparent(scene, i) && !scene.meshes[scene.instances[i].mesh].indices.empty();
  return e;
}

}  // namespace sl
