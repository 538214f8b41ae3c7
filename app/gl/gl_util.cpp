#include "gl/gl_util.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <stdexcept>

#if defined(__SANITIZE_ADDRESS__)
#define SL_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SL_ASAN 1
#endif
#endif
#ifdef SL_ASAN
#include <dlfcn.h>
#include <link.h>
#endif

namespace sl {

static std::atomic<int> g_glErrors{0};

static void GLAPIENTRY onGlDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
                                        const GLchar* message, const void*) {
  if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP) return;
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
  // Compile errors reach the UI through ShaderLibrary::errors(), with file:line; they are not
  // API misuse and must not fail a test that breaks a shader on purpose.
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
  if (type == GL_DEBUG_TYPE_ERROR) {
    ++g_glErrors;
    std::fprintf(stderr, "GL error: %s\n", message);
  } else if (severity == GL_DEBUG_SEVERITY_HIGH) {
    std::fprintf(stderr, "GL warning: %s\n", message);
  }
}

void enableGlDebugOutput(bool synchronous) {
  glEnable(GL_DEBUG_OUTPUT);
  if (synchronous) glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onGlDebugMessage, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

int glDebugErrorCount() { return g_glErrors.load(); }
void resetGlDebugErrorCount() { g_glErrors = 0; }

std::string glRendererName() {
  const GLubyte* r = glGetString(GL_RENDERER);
  return r ? reinterpret_cast<const char*>(r) : "unknown";
}

void keepGlDriverLoaded() {
#ifdef SL_ASAN
  std::vector<std::string> drivers;
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* out) {
        const std::string name = info->dlpi_name ? info->dlpi_name : "";
        if (name.find("/dri/") != std::string::npos || name.find("libgallium") != std::string::npos)
          static_cast<std::vector<std::string>*>(out)->push_back(name);
        return 0;
      },
      &drivers);
  // RTLD_NOLOAD: only the already loaded driver; RTLD_NODELETE: dlclose no longer unmaps it.
  for (const auto& d : drivers) dlopen(d.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
#endif
}

void drawFullscreenTriangle() {
  GLuint vao = 0;
  glCreateVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDeleteVertexArrays(1, &vao);
}

bool isSoftwareRenderer() {
  std::string r = glRendererName();
  return r.find("llvmpipe") != std::string::npos || r.find("softpipe") != std::string::npos ||
         r.find("SwiftShader") != std::string::npos;
}

GlDebugGroup::GlDebugGroup(const std::string& name) {
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, static_cast<GLsizei>(name.size()), name.c_str());
}
GlDebugGroup::~GlDebugGroup() { glPopDebugGroup(); }

void label(GLenum identifier, GLuint name, const std::string& text) {
  glObjectLabel(identifier, name, static_cast<GLsizei>(text.size()), text.c_str());
}

Texture2D::Texture2D(GLenum internalFormat, int width, int height, const std::string& labelText)
    : width_(width), height_(height), format_(internalFormat) {
  glCreateTextures(GL_TEXTURE_2D, 1, &id_);
  glTextureStorage2D(id_, 1, internalFormat, width, height);
  setFilter(GL_NEAREST, GL_NEAREST);
  setClampToEdge();
  label(GL_TEXTURE, id_, labelText);
}

Texture2D Texture2D::array(GLenum internalFormat, int width, int height, int layers, int levels,
                           const std::string& labelText) {
  Texture2D t;
  t.width_ = width;
  t.height_ = height;
  t.layers_ = std::max(layers, 1);
  t.levels_ = std::max(levels, 1);
  t.format_ = internalFormat;
  t.target_ = GL_TEXTURE_2D_ARRAY;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &t.id_);
  glTextureStorage3D(t.id_, t.levels_, internalFormat, width, height, t.layers_);
  t.setFilter(GL_NEAREST, GL_NEAREST);
  t.setClampToEdge();
  label(GL_TEXTURE, t.id_, labelText);
  return t;
}

Texture2D::~Texture2D() {
  if (id_) glDeleteTextures(1, &id_);
}

Texture2D::Texture2D(Texture2D&& o) noexcept { *this = std::move(o); }
Texture2D& Texture2D::operator=(Texture2D&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteTextures(1, &id_);
    id_ = o.id_;
    width_ = o.width_;
    height_ = o.height_;
    format_ = o.format_;
    target_ = o.target_;
    layers_ = o.layers_;
    levels_ = o.levels_;
    o.id_ = 0;
  }
  return *this;
}

void Texture2D::setFilter(GLenum minFilter, GLenum magFilter) {
  glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
  glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
}

void Texture2D::setClampToEdge() {
  glTextureParameteri(id_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

std::vector<float> Texture2D::readFloats(int channels) const {
  static const GLenum formats[] = {0, GL_RED, GL_RG, GL_RGB, GL_RGBA};
  GLenum fmt =
      (format_ == GL_DEPTH_COMPONENT32F || format_ == GL_DEPTH_COMPONENT24) ? GL_DEPTH_COMPONENT : formats[channels];
  std::vector<float> out(static_cast<size_t>(width_) * height_ * std::max(layers_, 1) * channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(id_, 0, fmt, GL_FLOAT, static_cast<GLsizei>(out.size() * sizeof(float)), out.data());
  return out;
}

std::vector<uint32_t> Texture2D::readUints(int channels) const {
  static const GLenum formats[] = {0, GL_RED_INTEGER, GL_RG_INTEGER, GL_RGB_INTEGER, GL_RGBA_INTEGER};
  std::vector<uint32_t> out(static_cast<size_t>(width_) * height_ * channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(id_, 0, formats[channels], GL_UNSIGNED_INT, static_cast<GLsizei>(out.size() * sizeof(uint32_t)),
                    out.data());
  return out;
}

std::vector<unsigned char> Texture2D::readRgba8() const {
  std::vector<unsigned char> out(static_cast<size_t>(width_) * height_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(id_, 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(out.size()), out.data());
  return out;
}

Framebuffer::Framebuffer(const std::string& labelText) {
  glCreateFramebuffers(1, &id_);
  label(GL_FRAMEBUFFER, id_, labelText);
}
Framebuffer::~Framebuffer() {
  if (id_) glDeleteFramebuffers(1, &id_);
}
Framebuffer::Framebuffer(Framebuffer&& o) noexcept { *this = std::move(o); }
Framebuffer& Framebuffer::operator=(Framebuffer&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteFramebuffers(1, &id_);
    id_ = o.id_;
    width_ = o.width_;
    height_ = o.height_;
    o.id_ = 0;
  }
  return *this;
}

void Framebuffer::attach(const std::vector<const Texture2D*>& colors, const Texture2D* depth) {
  attachLayer(colors, depth, 0);  // plain textures ignore the layer
}

void Framebuffer::attachLayer(const std::vector<const Texture2D*>& colors, const Texture2D* depth, int layer,
                              int level) {
  std::vector<GLenum> drawBuffers;
  auto attachOne = [&](GLenum point, const Texture2D* t) {
    if (t->layers() > 0)
      glNamedFramebufferTextureLayer(id_, point, t->id(), level, layer);
    else
      glNamedFramebufferTexture(id_, point, t->id(), level);
    width_ = std::max(1, t->width() >> level);
    height_ = std::max(1, t->height() >> level);
  };
  for (size_t i = 0; i < colors.size(); ++i) {
    attachOne(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i), colors[i]);
    drawBuffers.push_back(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i));
  }
  if (depth) attachOne(GL_DEPTH_ATTACHMENT, depth);
  if (drawBuffers.empty())
    glNamedFramebufferDrawBuffer(id_, GL_NONE);
  else
    glNamedFramebufferDrawBuffers(id_, static_cast<GLsizei>(drawBuffers.size()), drawBuffers.data());
  GLenum status = glCheckNamedFramebufferStatus(id_, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("framebuffer incomplete (status 0x" + std::to_string(status) + ")");
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, id_);
  glViewport(0, 0, width_, height_);
}

}  // namespace sl
