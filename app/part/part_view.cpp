#include "part/part_view.h"

#include "gl/gl_util.h"
#include "gl/shader_library.h"
#include "gl/texture_units.h"

namespace sl {

void drawPartView(const PartContext& ctx, Texture2D* target, const std::string& fragment,
                  const PartViewOptions& options) {
  const ProgramSpec spec{"view " + fragment + (options.defines.empty() ? "" : " " + options.defines),
                         {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, fragment}},
                         options.defines + ctx.techniquePrelude};
  Program& p = ctx.shaders->get(spec);
  if (!p.valid()) return;  // the library reports the error; the last good program is kept there
  Framebuffer fbo("view target");
  fbo.attach({target}, nullptr);
  fbo.bind();
  glViewport(0, 0, target->width(), target->height());
  p.use();
  TextureUnits units;
  ctx.bindTechnique(p, units);
  if (options.withGBuffer) ctx.bindGBuffer(p, units);
  if (options.bind) options.bind(p, units);
  p.set("u_viewSize", glm::vec2(target->width(), target->height()));
  ctx.drawFullscreen();
}

}  // namespace sl
