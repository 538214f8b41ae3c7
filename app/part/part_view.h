// A part's debug view, drawn the one way every part draws one: a fullscreen pass of the view's
// fragment shader (with the technique's modules, so it can call the part's GLSL) into the view
// target, every part's bindings and `u_viewSize` set. Call it inside the view's frame-graph pass.
#pragma once

#include "part/part.h"

#include <functional>
#include <string>

namespace sl {

struct PartViewOptions {
  std::string defines;       // prepended to the technique prelude (also part of the program's name)
  bool withGBuffer = false;  // also bind the G-buffer (u_gPosition, u_gNormal, ...)
  std::function<void(const Program&, TextureUnits&)> bind;  // the view's own inputs, if any
};

void drawPartView(const PartContext& ctx, Texture2D* target, const std::string& fragment,
                  const PartViewOptions& options = {});

}  // namespace sl
