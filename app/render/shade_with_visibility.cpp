// Renderer::shadeWithVisibility: the deferred shade pass over a frame's G-buffer with a
// visibility given from outside (the ray-traced reference's), so the image metric compares a
// technique's colour with the very same shading formula, never a CPU copy of it.
#include "part/uniforms.h"
#include "render/gpu_scene.h"
#include "render/renderer.h"

#include "gl/texture_units.h"

#include <stdexcept>

namespace sl {

std::string Renderer::shadePrelude() const {
  // common/light.glsl specialises on the light type at compile time, as the techniques' passes do.
  return scene_ ? lightDefines(scene_->light) : "";
}

std::vector<unsigned char> Renderer::shadeWithVisibility(const FrameInput& in, const std::vector<float>& visibility,
                                                         const std::vector<std::vector<float>>& others) {
  if (!scene_) throw std::runtime_error("renderer: no scene loaded");
  const int w = in.width, h = in.height;
  if (!gPosition_ || w != width_ || h != height_)
    throw std::invalid_argument("shadeWithVisibility: " + std::to_string(w) + "x" + std::to_string(h) +
                                " is not the size of the last rendered frame");
  if (visibility.size() != static_cast<size_t>(w) * static_cast<size_t>(h))
    throw std::invalid_argument("shadeWithVisibility: " + std::to_string(visibility.size()) +
                                " visibility values for " + std::to_string(w) + "x" + std::to_string(h) + " pixels");
  GlDebugGroup group("shade with visibility");
  const PreviousFrame self{cameraView(in.camera),
                           cameraProjection(in.camera, static_cast<float>(w) / static_cast<float>(h)), in.time, epoch_};
  const glm::mat4 viewProj = self.proj * self.view;
  // Techniques shade forward, so the G-buffer of a measured frame is usually not drawn. Drawn
  // here without motion (its previous frame is itself): only the shading reads it.
  const GBufferContent& held = gbufferHolds_;
  if (held.epoch != epoch_ || held.viewProj != viewProj || held.time != in.time) drawGBuffer(viewProj, in.time, self);

  if (!substColor_ || substColor_->width() != w || substColor_->height() != h) {
    substVisibility_ = std::make_unique<Texture2D>(GL_R32F, w, h, "substituted visibility");
    substColor_ = std::make_unique<Texture2D>(GL_RGBA8, w, h, "color with substituted visibility");
    substFbo_ = Framebuffer("shade with visibility");
    substFbo_.attach({substColor_.get()}, nullptr);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(substVisibility_->id(), 0, 0, 0, w, h, GL_RED, GL_FLOAT, visibility.data());
  if (!scene_->otherLights.empty()) {
    const Texture2D& otherDirect = substitutedOtherDirect(w, h, others);
    const bool built = shadeLights(substFbo_, *substVisibility_, otherDirect);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!built) return {};
    return substColor_->readRgba8();
  }

  ProgramSpec spec{"shade",
                   {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "passes/shade.frag"}},
                   shadePrelude()};
  Program& p = shaders_.get(spec);
  if (!p.valid()) return {};
  substFbo_.bind();
  p.use();
  setLightUniforms(p, scene_->light);
  TextureUnits units;
  bindGBuffer(p, units, substVisibility_.get());
  drawFullscreen();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return substColor_->readRgba8();
}

}  // namespace sl
