#include "part/shadow_draw_plan.h"

#include <algorithm>

namespace sl {

glm::mat4 ShadowTile::clip(const glm::mat4& layerViewProj) const {
  glm::mat4 page(1.0f);
  page[0][0] = transform.x, page[1][1] = transform.y, page[3][0] = transform.z, page[3][1] = transform.w;
  return page * layerViewProj;
}

std::vector<std::pair<GLenum, std::string>> casterStages(const LightSpace& lightSpace, const std::string& fragment) {
  const bool warped = std::any_of(lightSpace.views.begin(), lightSpace.views.end(),
                                  [](const LightView& v) { return v.projection == LightView::Projection::LogWarp; });
  if (!warped) return {{GL_VERTEX_SHADER, "passes/shadow.vert"}, {GL_FRAGMENT_SHADER, fragment}};
  return {{GL_VERTEX_SHADER, "passes/shadow.vert"},
          {GL_TESS_CONTROL_SHADER, "passes/shadow_warp.tesc"},
          {GL_TESS_EVALUATION_SHADER, "passes/shadow_warp.tese"},
          {GL_FRAGMENT_SHADER, fragment}};
}

}  // namespace sl
