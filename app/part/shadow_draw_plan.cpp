#include "part/shadow_draw_plan.h"

#include <algorithm>

namespace sl {

glm::mat4 ShadowTile::clip(const glm::mat4& layerViewProj) const {
  glm::mat4 page(1.0f);
  page[0][0] = transform.x, page[1][1] = transform.y, page[3][0] = transform.z, page[3][1] = transform.w;
  return page * layerViewProj;
}

ShadowTile atlasTile(const glm::ivec4& rect) {
  ShadowTile t;
  t.rect = rect;
  t.wholeLayerViewport = true;
  return t;
}

std::vector<std::pair<GLenum, std::string>> casterStages(const LightSpace& lightSpace, const std::string& fragment) {
  const auto uses = [&](LightView::Projection kind) {
    return std::any_of(lightSpace.views.begin(), lightSpace.views.end(),
                       [&](const LightView& v) { return v.projection == kind; });
  };
  // Each bent projection has its own error bound for the chords (the control stage); the
  // evaluation stage places vertices through the layout's layoutClip for both.
  const char* control = uses(LightView::Projection::LogWarp)      ? "passes/shadow_warp.tesc"
                        : uses(LightView::Projection::Paraboloid) ? "passes/shadow_paraboloid.tesc"
                                                                  : nullptr;
  if (!control) return {{GL_VERTEX_SHADER, "passes/shadow.vert"}, {GL_FRAGMENT_SHADER, fragment}};
  return {{GL_VERTEX_SHADER, "passes/shadow.vert"},
          {GL_TESS_CONTROL_SHADER, control},
          {GL_TESS_EVALUATION_SHADER, "passes/shadow_warp.tese"},
          {GL_FRAGMENT_SHADER, fragment}};
}

std::string casterSortStage(const LightSpace& lightSpace) {
  const bool warped = std::any_of(lightSpace.views.begin(), lightSpace.views.end(), [](const LightView& v) {
    return v.projection == LightView::Projection::LogWarp && v.sortCasters;
  });
  return warped ? "passes/warp_classify.comp" : "";
}

std::vector<std::pair<GLenum, std::string>> withoutTessellation(std::vector<std::pair<GLenum, std::string>> stages) {
  std::erase_if(stages, [](const auto& stage) {
    return stage.first == GL_TESS_CONTROL_SHADER || stage.first == GL_TESS_EVALUATION_SHADER;
  });
  return stages;
}

}  // namespace sl
