#include "explorer/magnifier.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace sl {

namespace {
constexpr int kLensPixels = 160;
constexpr int kZoom = 8;
constexpr int kTexelsAcross = kLensPixels / kZoom;  // 20
constexpr float kOffsetFromMouse = 24.0f;
}  // namespace

void drawMagnifier(const MagnifierTarget& target, ImVec2 mouse) {
  if (!target.valid()) return;
  const float imageW = target.imageMax.x - target.imageMin.x;
  const float imageH = target.imageMax.y - target.imageMin.y;
  if (imageW <= 0 || imageH <= 0) return;

  // Texel under the mouse, counted from the top-left like the screen.
  const int texW = target.textureWidth, texH = target.textureHeight;
  int texelX = static_cast<int>(std::floor((mouse.x - target.imageMin.x) / imageW * texW));
  int texelY = static_cast<int>(std::floor((mouse.y - target.imageMin.y) / imageH * texH));
  texelX = std::clamp(texelX, 0, texW - 1);
  texelY = std::clamp(texelY, 0, texH - 1);

  // Window of texels around it, pushed inside the texture near the borders so the lens never
  // shows clamped or wrapped texels (the outline then moves off-centre instead).
  const int firstX = std::clamp(texelX - kTexelsAcross / 2, 0, std::max(0, texW - kTexelsAcross));
  const int firstY = std::clamp(texelY - kTexelsAcross / 2, 0, std::max(0, texH - kTexelsAcross));
  // GL rows run bottom-up, so the top screen row firstY is v = 1 - firstY / texH.
  const ImVec2 uvTopLeft(float(firstX) / texW, 1.0f - float(firstY) / texH);
  const ImVec2 uvBottomRight(float(firstX + kTexelsAcross) / texW, 1.0f - float(firstY + kTexelsAcross) / texH);

  // Keep the lens on screen: flip to the other side of the mouse near the right/bottom edge.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float lensW = kLensPixels + 2.0f * ImGui::GetStyle().WindowPadding.x;
  const float lensH =
      kLensPixels + ImGui::GetTextLineHeightWithSpacing() * 3.0f + 2.0f * ImGui::GetStyle().WindowPadding.y;
  ImVec2 pos(mouse.x + kOffsetFromMouse, mouse.y + kOffsetFromMouse);
  if (pos.x + lensW > display.x) pos.x = mouse.x - kOffsetFromMouse - lensW;
  if (pos.y + lensH > display.y) pos.y = mouse.y - kOffsetFromMouse - lensH;
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowBgAlpha(0.92f);

  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoNav |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings;
  if (ImGui::Begin("##magnifier", nullptr, flags)) {
    const ImVec2 lensMin = ImGui::GetCursorScreenPos();
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(target.texture)), ImVec2(kLensPixels, kLensPixels),
                 uvTopLeft, uvBottomRight);
    // Outline the texel under the mouse, in a colour visible on both light and dark pixels.
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 cellMin(lensMin.x + float((texelX - firstX) * kZoom), lensMin.y + float((texelY - firstY) * kZoom));
    const ImVec2 cellMax(cellMin.x + kZoom, cellMin.y + kZoom);
    draw->AddRect(ImVec2(cellMin.x - 1, cellMin.y - 1), ImVec2(cellMax.x + 1, cellMax.y + 1), IM_COL32(0, 0, 0, 255));
    draw->AddRect(cellMin, cellMax, IM_COL32(255, 60, 200, 255));
    // Texel coordinates in GL convention (y up) so they match shader gl_FragCoord values.
    // Wrapped to the lens width: a long technique label must not widen the window.
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + kLensPixels);
    ImGui::Text("%dx  texel %d, %d", kZoom, texelX, texH - 1 - texelY);
    ImGui::TextDisabled("%s", target.label.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

}  // namespace sl
