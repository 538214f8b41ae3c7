// The tiled maps' depth-discontinuity term (criterion distance, layouts/virtual_request.glsl)
// asks, at the atlas texel a pixel falls on, for the largest second difference of the light's
// depth over the 3x3 texels around it. The marking pass fetched those nine texels for every
// pixel (about 10 ms of its 30 at 1280x720 on llvmpipe); they change only where the shadow pass
// draws a page, so the bend is kept per atlas texel and recomputed for the tiles drawn since the
// last marking (none while nothing moves): one fetch per pixel.
#pragma once

#include "gl/gl_util.h"

#include <string>
#include <vector>

namespace sl {

class ShaderLibrary;

class VirtualDepthBend {
 public:
  VirtualDepthBend() = default;
  ~VirtualDepthBend();
  VirtualDepthBend(const VirtualDepthBend&) = delete;
  VirtualDepthBend& operator=(const VirtualDepthBend&) = delete;

  // Atlas tiles the shadow pass is about to draw (their bend is stale from then on).
  void tilesDrawn(const std::vector<int>& tiles);
  // Brings the bend up to date with `depth` (the atlas, layer 0: tiles of `page` texels,
  // `poolSide` per side; `defines` the layout's): the tiles drawn since the last call. Returns
  // the texture to read, 0 when there is none (no atlas yet, or the program failed: its error is
  // shown).
  GLuint update(ShaderLibrary& shaders, const Texture2D* depth, int page, int poolSide, const std::string& defines);

 private:
  Texture2D bend_;
  GLuint tileList_ = 0;
  std::vector<char> stale_;  // per tile: drawn since its bend was computed
};

}  // namespace sl
