// A headless OpenGL 3.3 core context through EGL (libglvnd's libEGL; GL entry points
// from libepoxy). No window and no X server: an EGL device (EGL_EXT_platform_device) or
// Mesa's surfaceless platform, drawing into framebuffer objects only. Or a window's
// context that someone else made (velocity::GlContextProvider: the presenter's SDL GL
// context), bound through the provider and never released or destroyed here.
#pragma once

#include <epoxy/egl.h>

#include <string>

#include "velocity/backend.hpp"

namespace velocity::gpu {

class Context {
 public:
  // Makes the context. `hardware_only`: refuse a software driver (Mesa's llvmpipe,
  // softpipe, SwiftShader), throwing velocity::Error that says so; otherwise a hardware
  // device when there is one, else the software one. Throws velocity::Error naming what
  // was missing: libEGL, an EGL device or platform, an OpenGL 3.3 core context.
  explicit Context(bool hardware_only);
  // A window's context: checked for OpenGL 3.3 core (and, with `hardware_only`, for a
  // hardware driver); throws velocity::Error saying what it lacks.
  Context(GlContextProvider& window, bool hardware_only);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // Binds the context to the calling thread (release: to none), so that a renderer may
  // move between threads as the CPU one may, one at a time. Throws velocity::Error.
  void make_current() const;
  void release() const;  // (a window's context stays bound: its thread draws and swaps)
  // velocity::Error when the driver reports the context lost (a GPU reset).
  void check_lost(const char* where) const;

  // What was made, e.g. "OpenGL 4.5 (Core Profile) Mesa 22.3.6 on llvmpipe (LLVM 15.0.6, 256 bits), EGL surfaceless".
  const std::string& description() const { return description_; }
  bool software() const { return software_; }
  // Whether this is a window's context (the GPU backend may present to it).
  bool windowed() const { return window_ != nullptr; }

 private:
  // Reads the version and renderer of the bound context; throws when it is under 3.3
  // or, with `hardware_only`, a software driver's.
  void describe(const std::string& where, bool hardware_only);

  GlContextProvider* window_ = nullptr;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  bool robust_ = false;
  bool software_ = false;
  std::string description_;
};

// Whether a GL renderer string names a software rasterizer.
bool is_software_renderer(const std::string& renderer);

// Holds the context current for a scope, and releases it after.
class Current {
 public:
  explicit Current(const Context& c) : c_(c) { c_.make_current(); }
  ~Current() { c_.release(); }
  Current(const Current&) = delete;
  Current& operator=(const Current&) = delete;

 private:
  const Context& c_;
};

}  // namespace velocity::gpu
