// Magnifier lens: shows the texels under the mouse enlarged with no filtering, so shadow-map
// aliasing, PCF steps and accumulation noise can be judged pixel by pixel.
#pragma once

#include <imgui.h>

#include <string>

namespace sl {

// An on-screen image and the texture it shows (drawn with flipped v, as GL textures are).
struct MagnifierTarget {
  unsigned int texture = 0;  // GL name; its filter must be GL_NEAREST for crisp texels
  int textureWidth = 0, textureHeight = 0;
  ImVec2 imageMin, imageMax;  // where the image is drawn, in ImGui screen coordinates
  std::string label;          // what is shown ("pcf (focused + depth-pcf)", "shadow map")
  bool valid() const { return texture != 0 && textureWidth > 0 && textureHeight > 0; }
};

// Draws the lens window next to `mouse` (which must lie over target's image).
void drawMagnifier(const MagnifierTarget& target, ImVec2 mouse);

}  // namespace sl
