// Small RAII wrappers and debugging helpers over OpenGL 4.5 direct state access.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <string>
#include <vector>

namespace sl {

// Routes KHR_debug messages to stderr and counts errors, so tests can fail on any GL error.
void enableGlDebugOutput(bool synchronous);
int glDebugErrorCount();
void resetGlDebugErrorCount();
std::string glRendererName();
// Sanitizer builds only (a no-op otherwise); call once a context is current. Mesa dlcloses
// its DRI driver when the display goes away, which unmaps the driver's globals: LeakSanitizer
// then reports the blocks only those globals pointed to as leaks of an unnamed module, which
// no suppression can match. Keeping the driver mapped until exit leaves them reachable, so
// what LeakSanitizer still reports is real and names the driver.
void keepGlDriverLoaded();
bool isSoftwareRenderer();  // llvmpipe/softpipe: timer queries there do not measure the work
// One triangle of three vertices with no attributes (passes/fullscreen.vert makes the
// positions from gl_VertexID). A core profile still wants a vertex array bound: a throwaway one
// keeps the caller free of per-context GL state (tests open several contexts). The renderer's
// own fullscreen draw keeps a vertex array of its context instead.
void drawFullscreenTriangle();

// Named scope in a captured frame (RenderDoc, apitrace).
class GlDebugGroup {
 public:
  explicit GlDebugGroup(const std::string& name);
  ~GlDebugGroup();
};

class Texture2D {
 public:
  Texture2D() = default;
  Texture2D(GLenum internalFormat, int width, int height, const std::string& label);
  // A GL_TEXTURE_2D_ARRAY of `layers` (>= 1) with `levels` mip levels (shadow maps of layouts
  // with several light views, representations with mip-maps).
  static Texture2D array(GLenum internalFormat, int width, int height, int layers, int levels,
                         const std::string& label);
  ~Texture2D();
  Texture2D(Texture2D&& o) noexcept;
  Texture2D& operator=(Texture2D&& o) noexcept;
  Texture2D(const Texture2D&) = delete;
  Texture2D& operator=(const Texture2D&) = delete;

  GLuint id() const { return id_; }
  int width() const { return width_; }
  int height() const { return height_; }
  GLenum format() const { return format_; }
  GLenum target() const { return target_; }
  int layers() const { return layers_; }  // 0 for a plain 2D texture
  int levels() const { return levels_; }
  explicit operator bool() const { return id_ != 0; }
  void setFilter(GLenum minFilter, GLenum magFilter);
  void setClampToEdge();
  // Readback, rows bottom-up as GL returns them.
  std::vector<float> readFloats(int channels) const;
  std::vector<unsigned char> readRgba8() const;
  std::vector<uint32_t> readUints(int channels) const;  // integer formats (GL_RGBA32UI, ...)

 private:
  GLuint id_ = 0;
  int width_ = 0, height_ = 0, layers_ = 0, levels_ = 1;
  GLenum format_ = 0, target_ = GL_TEXTURE_2D;
};

class Framebuffer {
 public:
  Framebuffer() = default;
  explicit Framebuffer(const std::string& label);
  ~Framebuffer();
  Framebuffer(Framebuffer&& o) noexcept;
  Framebuffer& operator=(Framebuffer&& o) noexcept;
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  GLuint id() const { return id_; }
  // Attaches colour targets in order (COLOR0..n) and an optional depth target; throws if
  // the driver reports the combination incomplete.
  void attach(const std::vector<const Texture2D*>& colors, const Texture2D* depth);
  // The same with one layer (and mip level) of array textures attached; attach() is layer 0.
  void attachLayer(const std::vector<const Texture2D*>& colors, const Texture2D* depth, int layer, int level = 0);
  void bind() const;

 private:
  GLuint id_ = 0;
  int width_ = 0, height_ = 0;
};

void label(GLenum identifier, GLuint name, const std::string& text);

}  // namespace sl
