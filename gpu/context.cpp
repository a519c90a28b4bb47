// EGL: find a device, make an OpenGL 3.3 core context, say what it is.
#include "context.hpp"

#include <dlfcn.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <cstring>
#include <vector>

#include "velocity/error.hpp"

namespace velocity::gpu {

namespace {

std::string egl_error() {
  char s[32];
  std::snprintf(s, sizeof s, "EGL error 0x%04x", unsigned(eglGetError()));
  return s;
}

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

// libepoxy aborts the process when it cannot open a library it needs: check first.
void require_library(const char* const* names, const char* what) {
  for (const char* const* n = names; *n; ++n)
    if (dlopen(*n, RTLD_LAZY | RTLD_GLOBAL)) return;  // stays loaded: epoxy uses it
  throw Error(std::string("no ") + what + " (" + names[0] + " not found; Debian: libegl1 / libopengl0)");
}

struct Device {
  EGLDeviceEXT device;
  bool software;
  std::string name;  // its DRM node when it has one
};

std::vector<Device> list_devices() {
  std::vector<Device> out;
  if (!has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_EXT_device_enumeration")) return out;
  EGLint count = 0;
  if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return out;
  std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
  if (!eglQueryDevicesEXT(count, devices.data(), &count)) return out;
  for (EGLint i = 0; i < count; ++i) {
    const char* ext = eglQueryDeviceStringEXT(devices[size_t(i)], EGL_EXTENSIONS);
    Device d{devices[size_t(i)], has_extension(ext, "EGL_MESA_device_software"), ""};
    if (has_extension(ext, "EGL_EXT_device_drm"))
      if (const char* node = eglQueryDeviceStringEXT(d.device, EGL_DRM_DEVICE_FILE_EXT)) d.name = node;
    out.push_back(d);
  }
  return out;
}

}  // namespace

bool is_software_renderer(const std::string& renderer) {
  for (const char* s : {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer", "swrast"})
    if (renderer.find(s) != std::string::npos) return true;
  return false;
}

Context::Context(bool hardware_only) {
  static const char* const egl[] = {"libEGL.so.1", nullptr};
  static const char* const gl[] = {"libOpenGL.so.0", "libGL.so.1", nullptr};
  require_library(egl, "EGL");
  require_library(gl, "OpenGL library");

  // A hardware device first; the software one, or Mesa's surfaceless platform, only
  // when the caller takes software.
  const std::vector<Device> devices = list_devices();
  std::string where;
  for (const Device& d : devices) {
    if (d.software) continue;
    display_ = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, d.device, nullptr);
    where = "EGL device " + (d.name.empty() ? std::string("(no DRM node)") : d.name);
    if (display_ != EGL_NO_DISPLAY && eglInitialize(display_, nullptr, nullptr)) break;
    display_ = EGL_NO_DISPLAY;
  }
  if (display_ == EGL_NO_DISPLAY) {
    // The surfaceless platform: Mesa's, and also NVIDIA's, whose devices need not be
    // enumerable (an H200 in a virtual machine listed none). When only hardware will
    // do, the renderer it gives is checked below.
    if (has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_MESA_platform_surfaceless")) {
      display_ = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      where = "EGL surfaceless platform";
    }
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, nullptr, nullptr)) {
      display_ = EGL_NO_DISPLAY;
      bool any_software = false;
      for (const Device& d : devices) any_software = any_software || d.software;
      if (hardware_only)
        throw Error(devices.empty() ? "no EGL device (no GPU driver for EGL)"
                                    : any_software ? "only a software OpenGL driver (Mesa's llvmpipe): the CPU pipeline is faster"
                                                   : "no EGL device could be initialised");
      throw Error("no EGL device and no surfaceless EGL platform (" + egl_error() + ")");
    }
  }

  const char* ext = eglQueryString(display_, EGL_EXTENSIONS);
  if (!eglBindAPI(EGL_OPENGL_API)) {
    throw Error(where + " offers no desktop OpenGL (" + egl_error() + ")");
  }
  if (!has_extension(ext, "EGL_KHR_surfaceless_context") || !has_extension(ext, "EGL_KHR_no_config_context")) {
    throw Error(where + " lacks EGL_KHR_surfaceless_context or EGL_KHR_no_config_context (needed to draw headless)");
  }
  // Lose the context on a GPU reset, so that check_lost can say so, when the driver can.
  robust_ = has_extension(ext, "EGL_EXT_create_context_robustness");
  std::vector<EGLint> attribs = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT};
  if (robust_) attribs.insert(attribs.end(), {EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT, EGL_LOSE_CONTEXT_ON_RESET_EXT});
  attribs.push_back(EGL_NONE);
  context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs.data());
  if (context_ == EGL_NO_CONTEXT && robust_) {  // a driver may refuse the strategy: try without
    robust_ = false;
    attribs.resize(6), attribs.push_back(EGL_NONE);
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs.data());
  }
  if (context_ == EGL_NO_CONTEXT) {
    const std::string e = egl_error();
    throw Error(where + ": no OpenGL 3.3 core context (" + e + "; the driver's version may be too old)");
  }
  make_current();
  try {
    describe(where, hardware_only);
  } catch (...) {
    release();
    eglDestroyContext(display_, context_);
    throw;
  }
  release();
}

Context::Context(GlContextProvider& window, bool hardware_only) : window_(&window) {
  make_current();
  describe(window.name(), hardware_only);
}

void Context::describe(const std::string& where, bool hardware_only) {
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major), glGetIntegerv(GL_MINOR_VERSION, &minor);
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string r = renderer ? renderer : "?";
  software_ = is_software_renderer(r);
  description_ = std::string("OpenGL ") + (version ? version : "?") + " on " + r + ", " + where;
  if (major * 10 + minor < 33 || (hardware_only && software_))
    throw Error(software_ && hardware_only ? "only a software OpenGL driver (" + r + "): the CPU pipeline is faster"
                                           : "OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
                                                 " is too old (3.3 core needed): " + description_);
  // A compatibility context would draw too, but the shaders are written for core.
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  if (window_ && !(profile & GL_CONTEXT_CORE_PROFILE_BIT))
    throw Error("the window's OpenGL context is not a core profile (3.3 core needed): " + description_);
}

Context::~Context() {
  if (window_) return;  // the window's owner destroys it
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  // (The display is never terminated: EGL has one per device for the whole process,
  // and other renderers' contexts live on it.)
}

void Context::make_current() const {
  if (window_) {
    std::string error;
    if (!window_->is_current() && !window_->make_current(error))
      throw Error("the window's OpenGL context could not be made current (" + error + ")");
    return;
  }
  if (eglGetCurrentContext() == context_) return;
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
    throw Error("the GPU backend's OpenGL context could not be made current (" + egl_error() +
                "; is the renderer used from two threads at once?)");
}

void Context::release() const {
  if (window_) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

void Context::check_lost(const char* where) const {
  if (!robust_ || !epoxy_has_gl_extension("GL_ARB_robustness")) return;
  if (glGetGraphicsResetStatusARB() != GL_NO_ERROR) throw Error(std::string(where) + ": the GPU's OpenGL context was lost (a GPU reset)");
}

}  // namespace velocity::gpu
