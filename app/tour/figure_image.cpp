// RgbaImage and FigureFonts (see figure_image.h). ImFontAtlas works without an ImGui context:
// it only rasterizes glyphs into an alpha texture, which is blended here pixel for pixel.
#include "tour/figure_image.h"

#include "explorer/ui_scale.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace sl {
namespace {

// Decodes one UTF-8 code point at s[i] and advances i; malformed bytes become '?'.
unsigned decodeUtf8(const std::string& s, size_t& i) {
  const auto c = static_cast<unsigned char>(s[i++]);
  if (c < 0x80) return c;
  int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : -1;
  if (extra < 0) return '?';
  unsigned cp = c & (0x3F >> extra);
  for (int k = 0; k < extra; ++k) {
    if (i >= s.size() || (static_cast<unsigned char>(s[i]) & 0xC0) != 0x80) return '?';
    cp = (cp << 6) | (static_cast<unsigned char>(s[i++]) & 0x3F);
  }
  return cp;
}

uint8_t toByte(float v) { return static_cast<uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

}  // namespace

RgbaImage::RgbaImage(int w, int h, glm::vec3 fill) : width(w), height(h), pixels(size_t(w) * size_t(h) * 4) {
  fillRect(0, 0, w, h, fill);
}

void RgbaImage::fillRect(int x, int y, int w, int h, glm::vec3 colour) {
  const int x0 = std::max(x, 0), y0 = std::max(y, 0), x1 = std::min(x + w, width), y1 = std::min(y + h, height);
  for (int yy = y0; yy < y1; ++yy)
    for (int xx = x0; xx < x1; ++xx) {
      uint8_t* p = &pixels[(size_t(yy) * size_t(width) + size_t(xx)) * 4];
      p[0] = toByte(colour.r), p[1] = toByte(colour.g), p[2] = toByte(colour.b), p[3] = 255;
    }
}

void RgbaImage::blend(int x, int y, glm::vec3 colour, float alpha) {
  if (x < 0 || y < 0 || x >= width || y >= height || !(alpha > 0.0f)) return;
  uint8_t* d = &pixels[(size_t(y) * size_t(width) + size_t(x)) * 4];
  const float a = std::min(alpha, 1.0f);
  for (int ch = 0; ch < 3; ++ch) d[ch] = toByte(glm::mix(d[ch] / 255.0f, colour[ch], a));
}

void RgbaImage::blitBottomUp(const std::vector<unsigned char>& rgba, int w, int h, int x, int y) {
  for (int row = 0; row < h; ++row) {
    const int ty = y + row;
    if (ty < 0 || ty >= height) continue;
    for (int col = 0; col < w; ++col) {
      const int tx = x + col;
      if (tx < 0 || tx >= width) continue;
      const unsigned char* s = &rgba[(size_t(h - 1 - row) * size_t(w) + size_t(col)) * 4];
      uint8_t* d = &pixels[(size_t(ty) * size_t(width) + size_t(tx)) * 4];
      d[0] = s[0], d[1] = s[1], d[2] = s[2], d[3] = 255;
    }
  }
}

FigureFonts::FigureFonts(float bodyPixels, float titlePixels) : atlas_(std::make_unique<ImFontAtlas>()) {
  ImFontConfig cfg;
  // No oversampling: atlas pixels map one to one onto figure pixels.
  cfg.OversampleH = cfg.OversampleV = 1;
  cfg.PixelSnapH = true;
  for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf"}) {
    if (!std::filesystem::exists(path)) continue;
    body_ = atlas_->AddFontFromFileTTF(path, bodyPixels, &cfg, textGlyphRanges());
    title_ = atlas_->AddFontFromFileTTF(path, titlePixels, &cfg, textGlyphRanges());
    if (body_ && title_) break;
  }
  if (!body_ || !title_) {  // ImGui's own bitmap font, scaled to whole multiples of 13 px
    atlas_->Clear();
    ImFontConfig bc = cfg, tc = cfg;
    bc.SizePixels = 13.0f * std::max(1.0f, std::round(bodyPixels / 13.0f));
    tc.SizePixels = 13.0f * std::max(1.0f, std::round(titlePixels / 13.0f));
    body_ = atlas_->AddFontDefault(&bc);
    title_ = atlas_->AddFontDefault(&tc);
  }
  unsigned char* data = nullptr;
  atlas_->GetTexDataAsAlpha8(&data, &atlasW_, &atlasH_);
  alpha_.assign(data, data + size_t(atlasW_) * size_t(atlasH_));
}

FigureFonts::~FigureFonts() = default;

int FigureFonts::lineHeight(Style s) const {
  return static_cast<int>(std::ceil((s == Style::Title ? title_ : body_)->FontSize * 1.25f));
}

int FigureFonts::width(const std::string& utf8, Style s) const {
  const ImFont* f = s == Style::Title ? title_ : body_;
  float w = 0.0f;
  for (size_t i = 0; i < utf8.size();) w += f->GetCharAdvance(static_cast<ImWchar>(decodeUtf8(utf8, i)));
  return static_cast<int>(std::ceil(w));
}

std::vector<std::string> FigureFonts::wrap(const std::string& utf8, int maxWidth, Style s) const {
  std::vector<std::string> lines;
  std::string line, word;
  auto flushWord = [&] {
    if (word.empty()) return;
    const std::string candidate = line.empty() ? word : line + " " + word;
    if (!line.empty() && width(candidate, s) > maxWidth) {
      lines.push_back(line);
      line = word;
    } else {
      line = candidate;
    }
    word.clear();
  };
  for (char c : utf8) {
    if (c == ' ' || c == '\n') {
      flushWord();
      if (c == '\n') {
        lines.push_back(line);
        line.clear();
      }
    } else {
      word += c;
    }
  }
  flushWord();
  if (!line.empty()) lines.push_back(line);
  return lines;
}

void FigureFonts::draw(RgbaImage& img, int x, int y, const std::string& utf8, Style s, glm::vec3 colour) const {
  const ImFont* f = s == Style::Title ? title_ : body_;
  float pen = float(x);
  for (size_t i = 0; i < utf8.size();) {
    const ImFontGlyph* g = f->FindGlyph(static_cast<ImWchar>(decodeUtf8(utf8, i)));
    if (!g) continue;
    const int gx = static_cast<int>(std::round(pen + g->X0)), gy = y + static_cast<int>(std::round(g->Y0));
    const int u0 = static_cast<int>(std::round(g->U0 * atlasW_)), v0 = static_cast<int>(std::round(g->V0 * atlasH_));
    const int gw = static_cast<int>(std::round((g->U1 - g->U0) * atlasW_));
    const int gh = static_cast<int>(std::round((g->V1 - g->V0) * atlasH_));
    for (int row = 0; row < gh; ++row)
      for (int col = 0; col < gw; ++col) {
        const int tx = gx + col, ty = gy + row;
        if (tx < 0 || ty < 0 || tx >= img.width || ty >= img.height) continue;
        const float a = alpha_[size_t(v0 + row) * size_t(atlasW_) + size_t(u0 + col)] / 255.0f;
        uint8_t* d = &img.pixels[(size_t(ty) * size_t(img.width) + size_t(tx)) * 4];
        for (int ch = 0; ch < 3; ++ch) d[ch] = toByte(glm::mix(d[ch] / 255.0f, colour[ch], a));
      }
    pen += g->AdvanceX;
  }
}

}  // namespace sl
