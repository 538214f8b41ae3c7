#include "explorer/viewport_area.h"

#include "explorer/colour_key.h"
#include "explorer/error_panel.h"
#include "technique.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace sl {

namespace {

constexpr float kGap = 6.0f;              // between tiles and around thumbnails
constexpr float kThumbnailShare = 0.22f;  // of a tile's height, when thumbnails are shown
const ImU32 kHighlight = IM_COL32(255, 190, 60, 255);

ImTextureID toImTexture(const Texture2D* t) { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(t->id())); }

// GL textures start at the bottom row; ImGui images at the top.
void addFlippedImage(ImDrawList* draw, const Texture2D* t, ImVec2 min, ImVec2 max) {
  draw->AddImage(toImTexture(t), min, max, ImVec2(0, 1), ImVec2(1, 0));
}

// Largest rectangle of the given aspect centred in `size`.
ImVec2 fitAspect(ImVec2 size, float aspect) {
  if (size.x / std::max(size.y, 1.0f) > aspect) return ImVec2(size.y * aspect, size.y);
  return ImVec2(size.x, size.x / aspect);
}

void drawTileHeader(ImDrawList* draw, const ViewportTile& tile, const ViewportSlot& slot, int index) {
  const Viewport& vp = *slot.viewport;
  // A tour's name for the viewport comes first: it is what the caption talks about.
  std::string text = std::to_string(index + 1) + "  " +
                     (slot.title.empty() ? vp.technique.label() : slot.title + "   " + vp.technique.label());
  if (!slot.enlargedView.empty()) text += "   [" + slot.enlargedView + "]";
  // Every part's status (the faces a point light's layout drew, the irregular z-buffer's
  // overflow) and, in a scene of several lights, how many were shadowed and at what map sizes.
  const std::string status = vp.status();
  if (!status.empty()) text += "   " + status;
  const float textY = tile.headerMin.y + (tile.headerSize.y - ImGui::GetTextLineHeight()) * 0.5f;
  const ImVec2 headerMax(tile.headerMin.x + tile.headerSize.x, tile.headerMin.y + tile.headerSize.y);
  // A long status (pixel-correct's) does not fit a 2x2 tile: cut it with an ellipsis and show
  // the whole text when the header is hovered.
  const float room = tile.headerSize.x - 8.0f;
  std::string shown = text;
  const bool cut = ImGui::CalcTextSize(text.c_str()).x > room;
  if (cut) {
    while (!shown.empty() && ImGui::CalcTextSize((shown + "...").c_str()).x > room) shown.pop_back();
    shown += "...";
  }
  draw->PushClipRect(tile.headerMin, headerMax, true);
  draw->AddText(ImVec2(tile.headerMin.x + 4.0f, textY), IM_COL32(235, 235, 235, 255), shown.c_str());
  draw->PopClipRect();
  if (cut && ImGui::IsMouseHoveringRect(tile.headerMin, headerMax)) ImGui::SetTooltip("%s", text.c_str());
}

// The texture of a debug view: the renderer's, or the accuracy panel's for `error`.
const Texture2D* debugViewTexture(const ExplorerState& state, const Viewport& vp, int index, const std::string& name) {
  if (name == ErrorPanel::kViewName) return state.errorPanel ? state.errorPanel->errorTexture(index) : nullptr;
  return vp.viewTexture(name);
}

// Text centred in a rectangle, clipped to it (for views that have no image yet).
void placeholder(ImDrawList* draw, ImVec2 min, ImVec2 max, const std::string& text) {
  draw->AddRectFilled(min, max, IM_COL32(40, 40, 44, 255));
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  draw->PushClipRect(min, max, true);
  draw->AddText(ImVec2(std::max(min.x + 4.0f, (min.x + max.x - size.x) * 0.5f), (min.y + max.y - size.y) * 0.5f),
                IM_COL32(200, 200, 200, 255), text.c_str());
  draw->PopClipRect();
}

// Thumbnails in a row, each keeping the image aspect, name underneath.
void drawThumbnails(ImDrawList* draw, const ViewportTile& tile, ViewportSlot& slot, int index,
                    const ExplorerState& state) {
  Viewport& vp = *slot.viewport;
  std::vector<std::string> views = vp.shownViews;
  if (state.selectedViews.count(ErrorPanel::kViewName)) views.push_back(ErrorPanel::kViewName);
  if (views.empty() || tile.thumbsSize.y <= 0) return;
  const float labelH = ImGui::GetTextLineHeight();
  const float aspect = tile.imageSize.x / std::max(tile.imageSize.y, 1.0f);
  const int count = int(views.size());
  const float slotW = (tile.thumbsSize.x - kGap * float(count - 1)) / float(count);
  const ImVec2 thumb = fitAspect(ImVec2(slotW, tile.thumbsSize.y - labelH - kGap), aspect);

  for (int i = 0; i < count; ++i) {
    const std::string& name = views[size_t(i)];
    const ImVec2 min(tile.thumbsMin.x + float(i) * (slotW + kGap), tile.thumbsMin.y + kGap);
    const ImVec2 max(min.x + thumb.x, min.y + thumb.y);
    ImGui::SetCursorScreenPos(min);
    ImGui::PushID(index * 100 + i);
    const bool clicked = ImGui::InvisibleButton("thumbnail", thumb);
    const bool hovered = ImGui::IsItemHovered();
    ImGui::PopID();
    if (const Texture2D* tex = debugViewTexture(state, vp, index, name); tex && tex->id())
      addFlippedImage(draw, tex, min, max);
    else if (name == ErrorPanel::kViewName && state.errorPanel)
      placeholder(draw, min, max, state.errorPanel->errorViewStatus());
    else
      draw->AddRectFilled(min, max, IM_COL32(40, 40, 40, 255));
    const bool enlarged = slot.enlargedView == name;
    if (enlarged || hovered)
      draw->AddRect(ImVec2(min.x - 2, min.y - 2), ImVec2(max.x + 2, max.y + 2),
                    enlarged ? kHighlight : IM_COL32(200, 200, 200, 255), 0.0f, 0, 2.0f);
    draw->PushClipRect(ImVec2(min.x, max.y), ImVec2(min.x + slotW, max.y + labelH + 2), true);
    draw->AddText(ImVec2(min.x, max.y + 1), enlarged ? kHighlight : IM_COL32(200, 200, 200, 255), name.c_str());
    draw->PopClipRect();
    const ColourKey* key = viewColourKey(name);
    if (key && state.showColourKeys) drawCompactColourKey(draw, *key, min, max);
    if (hovered) {
      ImGui::BeginTooltip();
      ImGui::Text("%s: click to %s", name.c_str(), enlarged ? "show the colour image again" : "enlarge");
      if (key) {
        ImGui::Separator();
        colourKeyTooltipBody(*key);
      }
      ImGui::EndTooltip();
    }
    if (clicked) slot.enlargedView = enlarged ? "" : name;
  }
}

}  // namespace

float thumbnailShare(int viewportCount, int thumbnailsPerTile) {
  if (thumbnailsPerTile <= 0) return 0.0f;
  if (viewportCount >= 4) return kThumbnailShare;  // 2x2 tiles are short: "enlarge" shows a view large
  // One view under a tall tile gets close to the image's own size; two a third of the height.
  if (thumbnailsPerTile == 1) return 0.45f;
  if (thumbnailsPerTile == 2) return 0.33f;
  return kThumbnailShare;
}

MainAreaLayout layoutMainArea(ImVec2 areaMin, ImVec2 areaSize, int viewportCount, int thumbnailsPerTile,
                              ImVec2 framebufferScale) {
  MainAreaLayout layout;
  layout.areaMin = areaMin;
  layout.areaSize = areaSize;
  // 1 to 3 side by side (a caption's "left, middle, right"), 4 as 2x2.
  const int columns = viewportCount >= 4 ? 2 : std::max(1, viewportCount);
  const int rows = viewportCount >= 4 ? 2 : 1;
  const float tileW = std::floor((areaSize.x - kGap * float(columns + 1)) / float(columns));
  const float tileH = std::floor((areaSize.y - kGap * float(rows + 1)) / float(rows));
  const float headerH = std::floor(ImGui::GetTextLineHeight() + 8.0f);
  const float thumbsH = std::floor(tileH * thumbnailShare(viewportCount, thumbnailsPerTile));
  // Whole framebuffer pixels, so one rendered pixel is exactly one screen pixel (magnifier).
  const int renderW = std::max(1, int(std::floor(tileW * framebufferScale.x)));
  const int renderH = std::max(1, int(std::floor((tileH - headerH - thumbsH) * framebufferScale.y)));
  layout.renderWidth = renderW;
  layout.renderHeight = renderH;
  const ImVec2 imageSize(float(renderW) / framebufferScale.x, float(renderH) / framebufferScale.y);

  for (int i = 0; i < viewportCount; ++i) {
    const float x = std::floor(areaMin.x + kGap + float(i % columns) * (tileW + kGap));
    const float y = std::floor(areaMin.y + kGap + float(i / columns) * (tileH + kGap));
    ViewportTile tile;
    tile.headerMin = ImVec2(x, y);
    tile.headerSize = ImVec2(tileW, headerH);
    tile.imageMin = ImVec2(x, y + headerH);
    tile.imageSize = imageSize;
    tile.thumbsMin = ImVec2(x, y + headerH + imageSize.y);
    tile.thumbsSize = ImVec2(tileW, thumbsH);
    layout.tiles.push_back(tile);
  }
  return layout;
}

MainAreaResult drawMainArea(const MainAreaLayout& layout, ExplorerState& state) {
  MainAreaResult result;
  ImGui::SetNextWindowPos(layout.areaMin);
  ImGui::SetNextWindowSize(layout.areaSize);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(18, 18, 20, 255));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollWithMouse |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoNav;
  ImGui::Begin("##viewports", nullptr, flags | ImGuiWindowFlags_NoBackground);
  ImDrawList* draw = ImGui::GetWindowDrawList();

  for (int i = 0; i < int(layout.tiles.size()) && i < int(state.slots.size()); ++i) {
    ViewportSlot& slot = state.slots[size_t(i)];
    const ViewportTile& tile = layout.tiles[size_t(i)];
    if (!slot.viewport) continue;
    const Viewport& vp = *slot.viewport;
    drawTileHeader(draw, tile, slot, i);

    const ImVec2 imageMax(tile.imageMin.x + tile.imageSize.x, tile.imageMin.y + tile.imageSize.y);
    const Texture2D* shown =
        slot.enlargedView.empty() ? vp.colorTexture() : debugViewTexture(state, vp, i, slot.enlargedView);
    ImGui::SetCursorScreenPos(tile.imageMin);
    ImGui::PushID(i);
    ImGui::InvisibleButton("image", tile.imageSize,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const bool hovered = ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenBlockedByActiveItem);
    ImGui::PopID();
    if (shown && shown->id()) {
      result.blits.push_back({shown, tile.imageMin, imageMax});
    } else if (slot.enlargedView == ErrorPanel::kViewName && state.errorPanel) {
      placeholder(draw, tile.imageMin, imageMax, state.errorPanel->errorViewStatus());
    } else {
      draw->AddRectFilled(tile.imageMin, imageMax, IM_COL32(45, 20, 20, 255));
      draw->AddText(ImVec2(tile.imageMin.x + 10, tile.imageMin.y + 10), IM_COL32(255, 120, 120, 255),
                    "not rendered (see the error in the side panel)");
    }
    if (const ColourKey* key = viewColourKey(slot.enlargedView); key && state.showColourKeys)
      drawColourKey(draw, *key, tile.imageMin, imageMax);
    if (i == state.hoveredViewport || hovered)
      draw->AddRect(ImVec2(tile.imageMin.x - 1, tile.imageMin.y - 1), ImVec2(imageMax.x + 1, imageMax.y + 1),
                    state.looking ? kHighlight : IM_COL32(90, 90, 100, 255));
    if (hovered && shown && shown->id()) {
      result.hoveredViewport = i;
      result.hoveredImage.texture = shown->id();
      result.hoveredImage.textureWidth = shown->width();
      result.hoveredImage.textureHeight = shown->height();
      result.hoveredImage.imageMin = tile.imageMin;
      result.hoveredImage.imageMax = imageMax;
      result.hoveredImage.label = slot.enlargedView.empty() ? vp.technique.label() : slot.enlargedView;
    } else if (hovered) {
      result.hoveredViewport = i;
    }
    if (result.hoveredViewport == i) {
      result.hoveredTileMin = tile.imageMin;
      result.hoveredTileMax = ImVec2(tile.imageMin.x + tile.imageSize.x, tile.thumbsMin.y + tile.thumbsSize.y);
    }
    drawThumbnails(draw, tile, slot, i, state);
  }
  ImGui::End();
  ImGui::PopStyleColor();
  ImGui::PopStyleVar(2);
  return result;
}

void blitToScreen(const std::vector<ScreenBlit>& blits, int framebufferHeight, ImVec2 scale) {
  for (const ScreenBlit& b : blits) {
    if (!b.texture || !b.texture->id()) continue;
    Framebuffer source("explorer blit source");
    source.attach({b.texture}, nullptr);
    // Both are bottom-up in GL, so no flip; ImGui's y runs down from the top.
    const GLint x0 = GLint(std::lround(b.min.x * scale.x)), x1 = GLint(std::lround(b.max.x * scale.x));
    const GLint y0 = framebufferHeight - GLint(std::lround(b.max.y * scale.y));
    const GLint y1 = framebufferHeight - GLint(std::lround(b.min.y * scale.y));
    glBlitNamedFramebuffer(source.id(), 0, 0, 0, b.texture->width(), b.texture->height(), x0, y0, x1, y1,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
}

}  // namespace sl
