#include "gl/texture_units.h"

#include <stdexcept>

namespace sl {

TextureUnits::~TextureUnits() {
  for (const auto& [unit, bound] : samplers_)
    if (bound) glBindSampler(static_cast<GLuint>(unit), 0);
}

int TextureUnits::bind(const Program& p, const std::string& uniform, GLuint texture, GLuint sampler) {
  auto it = units_.find(uniform);
  int unit = 0;
  if (it != units_.end()) {
    unit = it->second;
  } else {
    GLint available = 16;
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &available);
    unit = static_cast<int>(units_.size());
    if (unit >= available)
      throw std::runtime_error("texture units: more than " + std::to_string(available) + " samplers in one pass ('" +
                               uniform + "')");
    units_[uniform] = unit;
  }
  glBindTextureUnit(static_cast<GLuint>(unit), texture);
  glBindSampler(static_cast<GLuint>(unit), sampler);
  samplers_[unit] = sampler != 0 || samplers_[unit];
  p.set(uniform, unit);
  return unit;
}

}  // namespace sl
