// What a scene calls for beyond a hard point-light shadow, derived once from the scene so that
// techniques (and the renderer's prelude) agree on it: an area light makes soft techniques read
// its radius and hard ones say in their status that they ignore it.
#pragma once

#include "scene/scene.h"

#include <string>

namespace sl {

struct SceneEffects {
  bool areaLight = false;  // light.radius > 0: the penumbra of a disk light is part of the truth
  float lightRadius = 0;   // spot: disk radius (world units); directional: tan of angular radius
};

SceneEffects sceneEffects(const Scene& scene);

// Status line of a technique that does not model the area light ("" when the scene has none).
std::string hardShadowNote(const SceneEffects& effects);

}  // namespace sl
