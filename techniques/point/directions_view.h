// The point-light layouts' `directions` view: every direction from the light as a panorama,
// tinted by the light view that holds it (shaders/views/light_directions.frag).
#pragma once

#include "part/colour_key.h"
#include "part/part.h"

#include <map>
#include <string>

namespace sl {

void addDirectionsViewPass(FrameGraph& graph, const PartContext& ctx);
void addDirectionsViewKey(std::map<std::string, ColourKey>& keys);

}  // namespace sl
