#include "gl/headless_context.h"

#include "gl/gl_util.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

namespace sl {

static EGLDisplay openDisplay(std::string& platform) {
  auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) return EGL_NO_DISPLAY;
  EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
    platform = "egl-surfaceless";
    return d;
  }
  // NVIDIA's driver offers devices rather than the Mesa surfaceless platform.
  auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (!queryDevices) return EGL_NO_DISPLAY;
  EGLint count = 0;
  queryDevices(0, nullptr, &count);
  std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
  queryDevices(count, devices.data(), &count);
  for (EGLDeviceEXT dev : devices) {
    d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, dev, nullptr);
    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
      platform = "egl-device";
      return d;
    }
  }
  return EGL_NO_DISPLAY;
}

HeadlessContext::HeadlessContext() {
  // tests/labels.cmake runs the `unit` tier with this set: a test there that needs a context is
  // labelled wrongly, and says so instead of passing on a machine that happens to have GL.
  const char* tier = std::getenv("SHADOWLAB_TEST_TIER");
  if (tier && std::string(tier) == "unit")
    throw std::runtime_error("a test labelled 'unit' (tests/labels.cmake) created a GL context: label it gl");
  EGLDisplay display = openDisplay(platform_);
  if (display == EGL_NO_DISPLAY)
    throw std::runtime_error("EGL: no surfaceless or device display (is libegl-mesa0 installed?)");
  if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL: cannot bind the OpenGL API");
  const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint numConfigs = 0;
  // Surfaceless contexts need no config; pass one when the driver offers it.
  eglChooseConfig(display, configAttribs, &config, 1, &numConfigs);
  const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                   4,
                                   EGL_CONTEXT_MINOR_VERSION,
                                   5,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                   EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                   EGL_CONTEXT_OPENGL_DEBUG,
                                   EGL_TRUE,
                                   EGL_NONE};
  EGLContext ctx =
      eglCreateContext(display, numConfigs > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, contextAttribs);
  if (ctx == EGL_NO_CONTEXT) {
    eglTerminate(display);
    throw std::runtime_error("EGL: cannot create an OpenGL 4.5 core context (error 0x" + std::to_string(eglGetError()) +
                             ")");
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
    eglDestroyContext(display, ctx);
    eglTerminate(display);
    throw std::runtime_error("EGL: cannot make the surfaceless context current");
  }
  display_ = display;
  context_ = ctx;
  keepGlDriverLoaded();
}

HeadlessContext::~HeadlessContext() {
  if (!display_) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

}  // namespace sl
