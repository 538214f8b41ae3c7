#include "part/part.h"

namespace sl {

LightSpace LayoutState::compute(const LayoutInput& in) { return layout_.compute(in); }

std::string Technique::label() const {
  std::string s = presetId + " (" + layout->id() + " + " + representation->id();
  if (accumulation->id() != "none") s += " + " + accumulation->id();
  return s + ")";
}

std::vector<std::pair<GLenum, std::string>> casterStages(const Layout& layout, const std::string& fragment) {
  if (!layout.tessellatesCasters()) return {{GL_VERTEX_SHADER, "passes/shadow.vert"}, {GL_FRAGMENT_SHADER, fragment}};
  return {{GL_VERTEX_SHADER, "passes/shadow.vert"},
          {GL_TESS_CONTROL_SHADER, "passes/shadow_warp.tesc"},
          {GL_TESS_EVALUATION_SHADER, "passes/shadow_warp.tese"},
          {GL_FRAGMENT_SHADER, fragment}};
}

}  // namespace sl
