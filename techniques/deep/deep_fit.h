// Where the deep shadow map's texels go (beyond Lokovic & Veach, who render the deep map with
// the light's own camera): only the part of each light view that semi-transparent casters and
// volumes cover needs a transmittance function, so the deep map is fitted to their light-space
// bounds, the survey's "focus the shadow map" applied to the deep casters alone. On `hair` the
// strands cover about a third of the focused view's width, so deep.size texels go three times
// as far per side.
#pragma once

#include "part/light_space.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

namespace sl {

// The deep map of one light view covers the window [origin, origin + size) of the view's map uv
// (0..1); mapping a layer uv into it and back.
struct DeepWindow {
  glm::vec2 origin{0.0f}, size{1.0f};
  glm::vec2 toDeep(glm::vec2 layerUv) const { return (layerUv - origin) / size; }
  glm::vec2 toLayer(glm::vec2 deepUv) const { return origin + deepUv * size; }
  bool operator==(const DeepWindow&) const = default;
};

// The window that holds every semi-transparent instance and volume of `scene` at `time` in
// `view`, padded by two deep texels, clamped to the map and no smaller than 1/maxMagnify of
// it; the whole map where the view bends casters (the log warp) or a caster's bounds reach
// behind a perspective light. Rounded so that the viewport which rasterizes it into deepSize²
// texels has integer origin and size (deepViewport gives them).
DeepWindow deepFitWindow(const Scene& scene, double time, const LightView& view, int deepSize, int maxMagnify);

// The GL viewport (x, y, width, height) that maps the window onto deepSize² texels.
glm::ivec4 deepViewport(const DeepWindow& window, int deepSize);

}  // namespace sl
