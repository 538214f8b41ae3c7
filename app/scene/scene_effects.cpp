#include "scene/scene_effects.h"

#include <cstdio>

namespace sl {

SceneEffects sceneEffects(const Scene& scene) {
  SceneEffects e;
  // Scene validation rejects a negative radius; a NaN one would fail every comparison, so it
  // is treated as a point light here rather than as an area light of undefined size.
  e.areaLight = scene.light.radius > 0.0f;
  e.lightRadius = e.areaLight ? scene.light.radius : 0.0f;
  return e;
}

std::string hardShadowNote(const SceneEffects& effects) {
  if (!effects.areaLight) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "hard: ignores light radius %g", effects.lightRadius);
  return buf;
}

}  // namespace sl
