#include "explorer/colour_key.h"

#include <algorithm>
#include <string>

namespace sl {

namespace {

ImU32 toU32(glm::vec3 c, float alpha = 1.0f) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, alpha)); }

const ImU32 kKeyBackground = IM_COL32(12, 12, 16, 215);
const ImU32 kKeyText = IM_COL32(235, 235, 235, 255);
const ImU32 kSwatchBorder = IM_COL32(160, 160, 160, 255);

// The gradient as adjacent quads between stops (AddRectFilledMultiColor interpolates each).
void gradientBar(ImDrawList* draw, const ColourKey& key, ImVec2 min, ImVec2 max) {
  const float width = max.x - min.x;
  for (size_t i = 1; i < key.stops.size(); ++i) {
    const ColourStop& a = key.stops[i - 1];
    const ColourStop& b = key.stops[i];
    const float x0 = min.x + a.position * width, x1 = min.x + b.position * width;
    draw->AddRectFilledMultiColor(ImVec2(x0, min.y), ImVec2(x1, max.y), toU32(a.colour), toU32(b.colour),
                                  toU32(b.colour), toU32(a.colour));
  }
  draw->AddRect(min, max, kSwatchBorder);
}

std::string titleWithUnit(const ColourKey& key) {
  return key.unit.empty() ? key.title : key.title + " [" + key.unit + "]";
}

}  // namespace

void drawColourKey(ImDrawList* draw, const ColourKey& key, ImVec2 imageMin, ImVec2 imageMax) {
  const float line = ImGui::GetTextLineHeight();
  const float pad = line * 0.4f;
  const std::string title = titleWithUnit(key);
  // Width: the widest text line, at least room for the bar's labels side by side.
  float width = ImGui::CalcTextSize(title.c_str()).x;
  float labelsWidth = 0.0f;
  for (const ColourStop& s : key.stops) labelsWidth += ImGui::CalcTextSize(s.label.c_str()).x + pad * 2.0f;
  width = std::max(width, labelsWidth);
  for (const SpecialColour& s : key.specials)
    width = std::max(width, line * 1.4f + ImGui::CalcTextSize(s.meaning.c_str()).x);
  if (!key.note.empty()) width = std::max(width, ImGui::CalcTextSize(key.note.c_str()).x);
  width = std::min(width, imageMax.x - imageMin.x - 4.0f * pad);
  const float barHeight = line * 0.8f;
  float height = line;  // title
  if (!key.stops.empty()) height += pad + barHeight + line;
  height += float(key.specials.size()) * (line + 2.0f);
  if (!key.note.empty()) height += line;

  const ImVec2 boxMin(imageMin.x + pad, imageMax.y - pad - height - 2.0f * pad);
  const ImVec2 boxMax(boxMin.x + width + 2.0f * pad, imageMax.y - pad);
  draw->PushClipRect(imageMin, imageMax, true);
  draw->AddRectFilled(boxMin, boxMax, kKeyBackground, 3.0f);
  ImVec2 cursor(boxMin.x + pad, boxMin.y + pad);
  draw->AddText(cursor, kKeyText, title.c_str());
  cursor.y += line;
  if (!key.stops.empty()) {
    cursor.y += pad;
    const ImVec2 barMin = cursor, barMax(cursor.x + width, cursor.y + barHeight);
    gradientBar(draw, key, barMin, barMax);
    for (const ColourStop& s : key.stops) {
      const float x = barMin.x + s.position * width;
      const float w = ImGui::CalcTextSize(s.label.c_str()).x;
      const float tx = std::clamp(x - w * 0.5f, barMin.x, barMax.x - w);
      draw->AddLine(ImVec2(x, barMax.y), ImVec2(x, barMax.y + 3.0f), kKeyText);
      draw->AddText(ImVec2(tx, barMax.y + 2.0f), kKeyText, s.label.c_str());
    }
    cursor.y += barHeight + line;
  }
  for (const SpecialColour& s : key.specials) {
    const ImVec2 swMin(cursor.x, cursor.y + 2.0f), swMax(cursor.x + line, cursor.y + line - 1.0f);
    draw->AddRectFilled(swMin, swMax, toU32(s.colour));
    draw->AddRect(swMin, swMax, kSwatchBorder);
    draw->AddText(ImVec2(cursor.x + line * 1.4f, cursor.y), kKeyText, s.meaning.c_str());
    cursor.y += line + 2.0f;
  }
  if (!key.note.empty()) draw->AddText(cursor, IM_COL32(190, 190, 195, 255), key.note.c_str());
  draw->PopClipRect();
}

// A categorical key in a thumbnail: its colours as a row of swatches (hover for their meaning).
void drawSwatchRow(ImDrawList* draw, const ColourKey& key, ImVec2 imageMin, ImVec2 imageMax) {
  const float side = std::max(6.0f, ImGui::GetTextLineHeight() * 0.55f);
  const ImVec2 rowMin(imageMin.x, imageMax.y - side - 4.0f);
  draw->PushClipRect(imageMin, imageMax, true);
  draw->AddRectFilled(rowMin, imageMax, kKeyBackground);
  float x = imageMin.x + 2.0f;
  for (const SpecialColour& s : key.specials) {
    if (x + side > imageMax.x) break;
    draw->AddRectFilled(ImVec2(x, rowMin.y + 2.0f), ImVec2(x + side, rowMin.y + 2.0f + side), toU32(s.colour));
    draw->AddRect(ImVec2(x, rowMin.y + 2.0f), ImVec2(x + side, rowMin.y + 2.0f + side), kSwatchBorder);
    x += side + 3.0f;
  }
  draw->PopClipRect();
}

void drawCompactColourKey(ImDrawList* draw, const ColourKey& key, ImVec2 imageMin, ImVec2 imageMax) {
  if (key.stops.size() < 2) {
    if (!key.specials.empty()) drawSwatchRow(draw, key, imageMin, imageMax);
    return;
  }
  const float line = ImGui::GetTextLineHeight();
  const float barHeight = std::max(4.0f, line * 0.35f);
  const ImVec2 barMin(imageMin.x + 2.0f, imageMax.y - barHeight - line - 2.0f);
  const ImVec2 barMax(imageMax.x - 2.0f, barMin.y + barHeight);
  draw->PushClipRect(imageMin, imageMax, true);
  draw->AddRectFilled(ImVec2(imageMin.x, barMin.y - 2.0f), imageMax, kKeyBackground);
  gradientBar(draw, key, barMin, barMax);
  // End labels, with the unit when there is room (a thumbnail can be narrow).
  const std::string& lo = key.stops.front().label;
  std::string hi = labelWithUnit(key.stops.back().label, key.unit);
  const float room = barMax.x - barMin.x;
  if (ImGui::CalcTextSize((lo + "  " + hi).c_str()).x > room) hi = key.stops.back().label;
  if (ImGui::CalcTextSize((lo + "  " + hi).c_str()).x <= room) {
    draw->AddText(ImVec2(barMin.x, barMax.y), kKeyText, lo.c_str());
    draw->AddText(ImVec2(barMax.x - ImGui::CalcTextSize(hi.c_str()).x, barMax.y), kKeyText, hi.c_str());
  }
  draw->PopClipRect();
}

void colourKeyTooltipBody(const ColourKey& key) {
  ImGui::TextUnformatted(titleWithUnit(key).c_str());
  if (!key.stops.empty()) {
    const float width = std::max(220.0f, ImGui::GetTextLineHeight() * 16.0f);
    const ImVec2 min = ImGui::GetCursorScreenPos();
    const float barHeight = ImGui::GetTextLineHeight() * 0.8f;
    gradientBar(ImGui::GetWindowDrawList(), key, min, ImVec2(min.x + width, min.y + barHeight));
    ImGui::Dummy(ImVec2(width, barHeight));
    std::string labels;
    for (const ColourStop& s : key.stops) labels += (labels.empty() ? "" : "   ") + s.label;
    ImGui::TextUnformatted(labels.c_str());
  }
  for (const SpecialColour& s : key.specials) {
    ImGui::ColorButton(s.meaning.c_str(), ImVec4(s.colour.r, s.colour.g, s.colour.b, 1.0f),
                       ImGuiColorEditFlags_NoTooltip, ImVec2(ImGui::GetTextLineHeight(), ImGui::GetTextLineHeight()));
    ImGui::SameLine();
    ImGui::TextUnformatted(s.meaning.c_str());
  }
  if (!key.note.empty()) ImGui::TextDisabled("%s", key.note.c_str());
}

}  // namespace sl
