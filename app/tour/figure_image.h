// A CPU image for headless figures, and text drawn into it with Dear ImGui's font rasterizer
// (the explorer's DejaVu Sans, or ImGui's built-in font): captions and titles are burnt in on the
// CPU, so a figure needs no window and no UI chrome, and looks the same on every driver.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct ImFont;
struct ImFontAtlas;

namespace sl {

struct RgbaImage {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // RGBA8, row 0 = top
  RgbaImage() = default;
  RgbaImage(int w, int h, glm::vec3 fill);
  void fillRect(int x, int y, int w, int h, glm::vec3 colour);
  // Mixes `colour` into one pixel with weight `alpha` (clipped to the image).
  void blend(int x, int y, glm::vec3 colour, float alpha);
  // Copies rows read back from GL (row 0 = bottom) of a w x h image to (x, y).
  void blitBottomUp(const std::vector<unsigned char>& rgba, int w, int h, int x, int y);
};

class FigureFonts {
 public:
  // Body text of `bodyPixels` and titles of `titlePixels` per line.
  FigureFonts(float bodyPixels, float titlePixels);
  ~FigureFonts();
  FigureFonts(const FigureFonts&) = delete;
  FigureFonts& operator=(const FigureFonts&) = delete;

  enum class Style { Body, Title };
  int lineHeight(Style s) const;
  int width(const std::string& utf8, Style s) const;
  // Greedy word wrap to `maxWidth` pixels (a word longer than a line gets a line of its own).
  std::vector<std::string> wrap(const std::string& utf8, int maxWidth, Style s) const;
  // Draws one line with its top-left at (x, y), clipped to the image.
  void draw(RgbaImage& img, int x, int y, const std::string& utf8, Style s, glm::vec3 colour) const;

 private:
  std::unique_ptr<ImFontAtlas> atlas_;
  ImFont* body_ = nullptr;
  ImFont* title_ = nullptr;
  std::vector<uint8_t> alpha_;
  int atlasW_ = 0, atlasH_ = 0;
};

}  // namespace sl
