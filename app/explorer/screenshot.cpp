#include "explorer/screenshot.h"

#include "gl/gl_util.h"

#include <epoxy/gl.h>
#include <stb_image_write.h>

#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace sl {

namespace {

// GL rows come bottom-up; PNG wants the top row first.
void flipRows(std::vector<unsigned char>& pixels, int height, size_t rowBytes) {
  std::vector<unsigned char> row(rowBytes);
  for (int y = 0; y < height / 2; ++y) {
    unsigned char* top = pixels.data() + size_t(y) * rowBytes;
    unsigned char* bottom = pixels.data() + size_t(height - 1 - y) * rowBytes;
    std::memcpy(row.data(), top, rowBytes);
    std::memcpy(top, bottom, rowBytes);
    std::memcpy(bottom, row.data(), rowBytes);
  }
}

}  // namespace

std::string writeWindowPng(int width, int height, const std::string& path) {
  if (width <= 0 || height <= 0) return "window has no pixels";
  std::vector<unsigned char> pixels(size_t(width) * height * 3);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);  // rows of width*3 bytes are not 4-byte aligned
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  const size_t rowBytes = size_t(width) * 3;
  flipRows(pixels, height, rowBytes);
  if (!stbi_write_png(path.c_str(), width, height, 3, pixels.data(), int(rowBytes))) return "could not write " + path;
  return "";
}

std::string writeTexturePng(const Texture2D& texture, const std::string& path) {
  const int width = texture.width(), height = texture.height();
  if (!texture.id() || width <= 0 || height <= 0) return "no image to write to " + path;
  std::vector<unsigned char> pixels(size_t(width) * height * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(texture.id(), 0, GL_RGB, GL_UNSIGNED_BYTE, GLsizei(pixels.size()), pixels.data());
  const size_t rowBytes = size_t(width) * 3;
  flipRows(pixels, height, rowBytes);
  if (!stbi_write_png(path.c_str(), width, height, 3, pixels.data(), int(rowBytes))) return "could not write " + path;
  return "";
}

std::string timestampedName(const std::string& suffix) {
  std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char buffer[64];
  std::strftime(buffer, sizeof buffer, "shadowlab-%Y%m%d-%H%M%S", &local);
  return buffer + suffix;
}

std::string timestampedScreenshotName() { return timestampedName(".png"); }

std::string defaultScreenshotDir(const char* (*env)(const char*)) {
  if (!env) env = [](const char* name) -> const char* { return std::getenv(name); };
  namespace fs = std::filesystem;
  if (const char* pictures = env("XDG_PICTURES_DIR"); pictures && *pictures)
    return (fs::path(pictures) / "shadowlab").string();
  if (const char* home = env("HOME"); home && *home) return (fs::path(home) / "Pictures" / "shadowlab").string();
  return "/tmp/shadowlab";
}

std::string ensureFolder(const std::string& dir) {
  if (dir.empty()) return "no folder given for screenshots";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) return "cannot create folder " + dir + ": " + ec.message();
  return "";
}

std::string writeTextFile(const std::string& dir, const std::string& name, const std::string& text) {
  if (std::string problem = ensureFolder(dir); !problem.empty()) throw std::runtime_error(problem);
  const std::filesystem::path path = std::filesystem::path(dir) / name;
  const std::filesystem::path temporary = path.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("could not write " + temporary.string());
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec)
    throw std::runtime_error("could not rename " + temporary.string() + " to " + path.string() + ": " + ec.message());
  return path.string();
}

}  // namespace sl
