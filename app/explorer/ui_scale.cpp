#include "explorer/ui_scale.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <filesystem>
#include <optional>

namespace sl {

const ImWchar* textGlyphRanges() {
  static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x206F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};
  return ranges;
}

void applyUiScale(float scale) {
  static std::optional<ImGuiStyle> baseStyle;
  if (!baseStyle) baseStyle = ImGui::GetStyle();
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  bool loaded = false;
  for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf"}) {
    if (std::filesystem::exists(path) &&
        io.Fonts->AddFontFromFileTTF(path, kBaseFontPixels * scale, nullptr, textGlyphRanges())) {
      loaded = true;
      break;
    }
  }
  if (!loaded) {
    ImFontConfig config;
    config.SizePixels = 13.0f * scale;
    io.Fonts->AddFontDefault(&config);
  }
  // 1.86's backend builds the font texture only with its other device objects: replace it here.
  if (io.BackendRendererUserData) {
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
  }
  ImGuiStyle& style = ImGui::GetStyle();
  style = *baseStyle;
  style.ScaleAllSizes(scale);
}

}  // namespace sl
