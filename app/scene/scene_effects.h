// What a scene calls for beyond a hard shadow of opaque casters from a point light, derived once
// from the scene so that techniques (and the renderer's prelude) agree on it and simulate only
// those effects: an area light makes soft techniques read its radius and hard ones say in their
// status that they ignore it; semi-transparent casters make the deep map run its passes ("a
// scene with no semi-transparent casters runs no deep pass").
#pragma once

#include "scene/scene.h"

#include <string>

namespace sl {

struct SceneEffects {
  bool areaLight = false;  // light.radius > 0: the penumbra of a disk light is part of the truth
  float lightRadius = 0;   // spot: disk radius (world units); directional: tan of angular radius
  // Some caster lets light through attenuated: a blended material (glTF BLEND, hair) on an
  // instance, or a participating medium (Scene::volumes).
  bool semiTransparent = false;
  // Participating media (Scene::volumes): the camera view marches them (the volumes pass).
  bool media = false;
};

SceneEffects sceneEffects(const Scene& scene);
// The same for one of its lights (a scene of several: each light's radius is its own).
SceneEffects sceneEffects(const Scene& scene, const Light& light);

// Status line of a technique that does not model the area light ("" when the scene has none).
std::string hardShadowNote(const SceneEffects& effects);
// True when instance `index` draws a semi-transparent (alphaBlend) material.
bool instanceSemiTransparent(const Scene& scene, size_t index);

}  // namespace sl
