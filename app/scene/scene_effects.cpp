#include "scene/scene_effects.h"

#include <cstdio>

namespace sl {

bool instanceSemiTransparent(const Scene& scene, size_t index);

SceneEffects sceneEffects(const Scene& scene) { return sceneEffects(scene, scene.light); }

SceneEffects sceneEffects(const Scene& scene, const Light& light) {
  SceneEffects e;
  // Scene validation rejects a negative radius; a NaN one would fail every comparison, so it
  // is treated as a point light here rather than as an area light of undefined size.
  e.areaLight = light.radius > 0.0f;
  e.lightRadius = e.areaLight ? light.radius : 0.0f;
  e.media = !scene.volumes.empty();
  e.semiTransparent = e.media;
  for (size_t i = 0; i < scene.instances.size() && !e.semiTransparent; ++i)
    e.semiTransparent = instanceSemiTransparent(scene, i) && !scene.meshes[scene.instances[i].mesh].indices.empty();
  return e;
}

std::string hardShadowNote(const SceneEffects& effects) {
  if (!effects.areaLight) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "hard: ignores light radius %g", effects.lightRadius);
  return buf;
}

bool instanceSemiTransparent(const Scene& scene, size_t index) {
  if (index >= scene.instances.size()) return false;
  const int mesh = scene.instances[index].mesh;
  if (mesh < 0 || static_cast<size_t>(mesh) >= scene.meshes.size()) return false;
  const int material = scene.meshes[static_cast<size_t>(mesh)].material;
  if (material < 0 || static_cast<size_t>(material) >= scene.materials.size()) return false;
  return scene.materials[static_cast<size_t>(material)].alphaBlend;
}

}  // namespace sl
