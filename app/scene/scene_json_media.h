// Internal to the JSON scene loader: the semi-transparent media of a scene file, `hair` and
// `volumes` (docs/scene-format.md), validated like the rest of the format.
#pragma once

#include "scene/json_reader.h"
#include "scene/scene.h"

#include <string>

namespace sl {

// Grows the strands of hair[i] on the named object (appendHair); throws SceneError naming the
// file and the field.
void parseHair(const JsonReader& r, const nlohmann::json& j, const std::string& where, Scene& scene);
// Appends volumes[i] to scene.volumes (at most 4).
void parseVolume(const JsonReader& r, const nlohmann::json& j, const std::string& where, Scene& scene);

}  // namespace sl
