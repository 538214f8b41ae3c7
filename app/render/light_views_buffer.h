// The light views of a layout as one uniform block (shaders/common/light_views.glsl, std140),
// bound at kLightViewsBinding for every pass of the viewport that owns it.
#pragma once

#include "part/part.h"

#include <epoxy/gl.h>

namespace sl {

constexpr GLuint kLightViewsBinding = 1;

class LightViewsBuffer {
 public:
  LightViewsBuffer();
  ~LightViewsBuffer();
  LightViewsBuffer(const LightViewsBuffer&) = delete;
  LightViewsBuffer& operator=(const LightViewsBuffer&) = delete;
  void upload(const LightSpace& ls);
  void bind() const;

 private:
  GLuint buffer_ = 0;
};

}  // namespace sl
