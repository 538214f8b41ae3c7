// Which light-transport effects a scene calls for, so that techniques simulate only those
// ("a scene with no semi-transparent casters runs no deep pass").
#pragma once

#include "scene/scene.h"

namespace sl {

struct SceneEffects {
  // Some caster lets light through attenuated: a blended material (glTF BLEND, hair) on an
  // instance, or a participating medium (Scene::volumes).
  bool semiTransparent = false;
};

SceneEffects sceneEffects(const Scene& scene);

// True when instance `index` draws a semi-transparent (alphaBlend) material.
bool instanceSemiTransparent(const Scene& scene, size_t index);

}  // namespace sl
