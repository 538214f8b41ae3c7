// One texture-unit allocator for every pass: the renderer, debug views, the parts of a technique
// and the materials ask it for a unit by sampler name instead of using fixed unit numbers, so
// parts written separately never collide. A name keeps its unit for the allocator's lifetime
// (one pass), so the programs of one pass (material variants) agree on it.
#pragma once

#include "gl/shader_library.h"

#include <epoxy/gl.h>

#include <functional>
#include <map>
#include <string>

namespace sl {

class TextureUnits {
 public:
  TextureUnits() = default;
  ~TextureUnits();  // unbinds the samplers it bound (textures stay bound: harmless)
  TextureUnits(const TextureUnits&) = delete;
  TextureUnits& operator=(const TextureUnits&) = delete;

  // Binds `texture` (and `sampler`, 0 = the texture's own parameters) to the unit of `uniform`
  // and sets the uniform on `p`; returns the unit.
  int bind(const Program& p, const std::string& uniform, GLuint texture, GLuint sampler = 0);
  int used() const { return static_cast<int>(units_.size()); }

 private:
  std::map<std::string, int> units_;
  std::map<int, bool> samplers_;
};

// What a pass sets on each program it draws with: uniforms, and textures through its units.
using ProgramSetup = std::function<void(const Program&, TextureUnits&)>;

}  // namespace sl
