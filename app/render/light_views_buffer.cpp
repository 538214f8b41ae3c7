#include "render/light_views_buffer.h"

#include "gl/gl_util.h"

#include <glm/gtc/type_ptr.hpp>

#include <cstring>

namespace sl {

namespace {

// std140 image of the block: arrays of mat4 and vec4 have no padding beyond their own size.
struct LightViewsBlock {
  float view[kMaxLightViews][16];
  float viewProj[kMaxLightViews][16];
  float range[kMaxLightViews][4];    // near, far, texel world size, perspective (0/1)
  float split[kMaxLightViews][4];    // camera view depth: from, to, blend band, LogPSM delta
  float window[kMaxLightViews][4];   // a paraboloid's fitted window: centre xy, zoom, unused
  float packing[kMaxLightViews][4];  // layer, packed triangle (-1: whole layer), offset in a shared layer
  float atlas[kMaxLightViews][4];    // the view's square of an atlas layer in uv: min xy, max xy (0: none)
  float info[4];                     // views, texels per side, scale in a shared layer, unused
};

}  // namespace

LightViewsBuffer::LightViewsBuffer() {
  glCreateBuffers(1, &buffer_);
  glNamedBufferData(buffer_, sizeof(LightViewsBlock), nullptr, GL_DYNAMIC_DRAW);
  label(GL_BUFFER, buffer_, "light views");
}

LightViewsBuffer::~LightViewsBuffer() { glDeleteBuffers(1, &buffer_); }

void LightViewsBuffer::upload(const LightSpace& ls) {
  LightViewsBlock block{};
  const size_t n = std::min<size_t>(ls.views.size(), kMaxLightViews);
  for (size_t i = 0; i < n; ++i) {
    const LightView& v = ls.views[i];
    std::memcpy(block.view[i], glm::value_ptr(v.view), sizeof(block.view[i]));
    std::memcpy(block.viewProj[i], glm::value_ptr(v.viewProj), sizeof(block.viewProj[i]));
    const float range[4] = {v.nearPlane, v.farPlane, v.texelWorldSize, v.perspective ? 1.0f : 0.0f};
    const float split[4] = {v.splitNear, v.splitFar, v.blendBand, v.logDelta};
    std::memcpy(block.range[i], range, sizeof(range));
    std::memcpy(block.split[i], split, sizeof(split));
    const float window[4] = {v.paraboloidWindow.x, v.paraboloidWindow.y, v.paraboloidWindow.z, v.paraboloidWindow.w};
    std::memcpy(block.window[i], window, sizeof(window));
    block.packing[i][0] = static_cast<float>(ls.layerOf(i));
    block.packing[i][1] = static_cast<float>(v.packedTriangle);
    block.packing[i][2] = ls.atlasPlacement.y;
    block.packing[i][3] = ls.atlasPlacement.z;
    if (v.atlasRect.z > 0 && ls.size > 0) {
      const float texel = 1.0f / static_cast<float>(ls.size);
      const float square[4] = {v.atlasRect.x * texel, v.atlasRect.y * texel, (v.atlasRect.x + v.atlasRect.z) * texel,
                               (v.atlasRect.y + v.atlasRect.w) * texel};
      std::memcpy(block.atlas[i], square, sizeof(square));
    }
  }
  block.info[0] = static_cast<float>(n);
  block.info[1] = static_cast<float>(ls.size);
  block.info[2] = ls.atlasPlacement.x;
  glNamedBufferSubData(buffer_, 0, sizeof(block), &block);
}

void LightViewsBuffer::bind() const { glBindBufferBase(GL_UNIFORM_BUFFER, kLightViewsBinding, buffer_); }

}  // namespace sl
