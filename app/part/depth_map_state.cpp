#include "part/depth_map_state.h"

#include "gl/texture_units.h"
#include "scene/scene_effects.h"

#include <stdexcept>

namespace sl {

// GL objects are made on first use: viewports (and their states) exist before a context does.
DepthMapState::DepthMapState(bool compare, bool shareable) : compare_(compare), shareable_(shareable) {}

void DepthMapState::createSampler() {
  glCreateSamplers(1, &sampler_);
  const bool compare = compare_;
  const GLint filter = compare ? GL_LINEAR : GL_NEAREST;
  glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, filter);
  glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, filter);
  glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  if (compare) {
    glSamplerParameteri(sampler_, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(sampler_, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  }
  label(GL_SAMPLER, sampler_, compare ? "shadow map: hardware compare" : "shadow map: raw depth");
}

DepthMapState::~DepthMapState() {
  if (sampler_) glDeleteSamplers(1, &sampler_);
}

bool DepthMapState::shareDepthLayer(const SharedDepthLayer* shared) {
  shared_ = shareable_ && shared && shared->depth && shared->framebuffer ? shared : nullptr;
  if (shared_) {  // its own map no longer read: its memory given back
    depth_ = Texture2D();
    layers_.clear();
  }
  return shared_ != nullptr;
}

void DepthMapState::prepare(int size, int layers, int /*views*/) {
  if (!sampler_) createSampler();
  if (shared_) return;
  if (depth_ && depth_.width() == size && depth_.layers() == layers) return;
  depth_ = Texture2D::array(GL_DEPTH_COMPONENT32F, size, size, layers, 1, "shadow map");
  layers_.clear();
  for (int l = 0; l < layers; ++l) {
    layers_.emplace_back("shadow map layer " + std::to_string(l));
    layers_.back().attachLayer({}, &depth_, l);
  }
}

void DepthMapState::beginShadowLayer(int layer) {
  if (shared_) throw std::logic_error("a shared depth layer is cleared by region, never whole");
  layers_.at(static_cast<size_t>(layer)).bind();
  glClearNamedFramebufferfi(layers_[static_cast<size_t>(layer)].id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
}

void DepthMapState::bindShadowLayer(int layer) {
  if (shared_)
    shared_->framebuffer->bind();
  else
    layers_.at(static_cast<size_t>(layer)).bind();
}

void DepthMapState::bind(const Program& p, TextureUnits& units) const {
  units.bind(p, "u_shadowMap", depthTexture()->id(), sampler_);
}

long long DepthMapState::texels() const {
  if (shared_) return 0;  // counted once, by the viewport that owns the shared layer
  return static_cast<long long>(depth_.width()) * depth_.height() * std::max(depth_.layers(), 1);
}

std::string DepthMapState::addPasses(FrameGraph&, const PartContext& ctx) {
  status_ = ctx.scene ? hardShadowNote(sceneEffects(*ctx.scene, ctx.shadowedLight())) : "";
  return ctx.shadowMap;
}

}  // namespace sl
