#include "explorer/screenshot.h"

#include <epoxy/gl.h>
#include <stb_image_write.h>

#include <cstring>
#include <ctime>
#include <vector>

namespace sl {

std::string writeWindowPng(int width, int height, const std::string& path) {
  if (width <= 0 || height <= 0) return "window has no pixels";
  std::vector<unsigned char> pixels(size_t(width) * height * 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);  // rows of width*3 bytes are not 4-byte aligned
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());

  // GL returns the bottom row first; PNG wants the top row first.
  const size_t rowBytes = size_t(width) * 3;
  std::vector<unsigned char> row(rowBytes);
  for (int y = 0; y < height / 2; ++y) {
    unsigned char* top = pixels.data() + size_t(y) * rowBytes;
    unsigned char* bottom = pixels.data() + size_t(height - 1 - y) * rowBytes;
    std::memcpy(row.data(), top, rowBytes);
    std::memcpy(top, bottom, rowBytes);
    std::memcpy(bottom, row.data(), rowBytes);
  }
  if (!stbi_write_png(path.c_str(), width, height, 3, pixels.data(), int(rowBytes))) return "could not write " + path;
  return "";
}

std::string timestampedScreenshotName() {
  std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char buffer[64];
  std::strftime(buffer, sizeof buffer, "shadowlab-%Y%m%d-%H%M%S.png", &local);
  return buffer;
}

}  // namespace sl
