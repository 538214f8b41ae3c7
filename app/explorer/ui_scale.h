// UI size for a projector: the font atlas is rebuilt at 16 px x scale (sharp, unlike
// FontGlobalScale's stretched bitmap) and every style size scaled with it.
#pragma once

#include <imgui.h>

namespace sl {

constexpr float kBaseFontPixels = 16.0f;

// Latin-1 and what captions, help texts and units use: Greek (α, σ), punctuation (— …), arrows
// (→ ↔) and maths (≈ ≤ ∞ √). The explorer's font and the headless figures' font load these.
const ImWchar* textGlyphRanges();

// Loads the UI font at kBaseFontPixels * scale and scales the style from the explorer's base
// style. Call before ImGui::NewFrame and after the OpenGL backend's init (it replaces the font
// texture); the first call records the base style, so make it after setting the style up.
void applyUiScale(float scale);

}  // namespace sl
