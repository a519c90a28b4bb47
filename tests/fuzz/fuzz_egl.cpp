// Fuzz target: the EGL vendor library (gl/egl) driven whole, as libglvnd's libEGL drives
// it: __egl_Main with an exports table of this file's, then the vendor's own EGL
// functions (found through its getProcAddress) called in random order with random
// attribute lists (names drawn near EGL's, any values, sometimes unterminated: the
// parsers stop at their limit), configurations, contexts and surfaces that exist, were
// destroyed, were terminated or never existed, and OpenGL drawing and read-back between.
// The current API is chosen by the input (OpenGL, OpenGL ES, none).
//
// Properties: no sanitizer report or leak; every call that fails sets an EGL error and
// every one that succeeds sets EGL_SUCCESS (eglGetError reads and resets it); chosen
// configurations have what was asked of their depth; a pbuffer's size is what was asked;
// what a context current on a pbuffer draws is read back from it. (Every byte is read
// in sequence, one statement each: a function's arguments are evaluated in an order
// that differs between compilers, and an input must replay the same under both.)
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <glvnd/libeglabi.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "fuzz_util.hpp"

extern "C" EGLBoolean __egl_Main(uint32_t version, const __EGLapiExports* exports, __EGLvendorInfo* vendor,
                                 __EGLapiImports* imports);

namespace {

class Bytes {
 public:
  Bytes(const uint8_t* data, size_t size) : p_(data), n_(size) {}
  bool empty() const { return n_ == 0; }
  uint8_t u8() {
    if (n_ == 0) return 0;
    --n_;
    return *p_++;
  }
  int32_t i32() {
    int32_t v = 0;
    for (int i = 0; i < 4; ++i) v = int32_t(uint32_t(v) << 8 | u8());
    return v;
  }

 private:
  const uint8_t* p_;
  size_t n_;
};

EGLenum g_api = EGL_OPENGL_API;
EGLenum current_api() { return g_api; }
void no_op() {}
__EGLvendorInfo* no_vendor() { return nullptr; }
EGLContext no_context() { return EGL_NO_CONTEXT; }
EGLDisplay no_display() { return EGL_NO_DISPLAY; }
EGLSurface no_surface(EGLint) { return EGL_NO_SURFACE; }
__eglMustCastToProperFunctionPointerType no_entry(__EGLvendorInfo*, int) { return nullptr; }
void set_error(EGLint) {}
EGLBoolean set_vendor(__EGLvendorInfo*) { return EGL_TRUE; }
__EGLvendorInfo* vendor_of_display(EGLDisplay) { return nullptr; }
__EGLvendorInfo* vendor_of_device(EGLDeviceEXT) { return nullptr; }
EGLBoolean set_device_vendor(EGLDeviceEXT, __EGLvendorInfo*) { return EGL_TRUE; }

const __EGLapiExports kExports = {no_op,        current_api,     no_vendor,         no_context,
                                  no_display,   no_surface,      no_entry,          set_error,
                                  set_vendor,   vendor_of_display, vendor_of_device, set_device_vendor};

struct Vendor {
  __EGLapiImports imports{};
  EGLint (*get_error)() = nullptr;
  EGLBoolean (*initialize)(EGLDisplay, EGLint*, EGLint*) = nullptr;
  EGLBoolean (*terminate)(EGLDisplay) = nullptr;
  EGLBoolean (*choose_config)(EGLDisplay, const EGLint*, EGLConfig*, EGLint, EGLint*) = nullptr;
  EGLBoolean (*get_configs)(EGLDisplay, EGLConfig*, EGLint, EGLint*) = nullptr;
  EGLBoolean (*get_config_attrib)(EGLDisplay, EGLConfig, EGLint, EGLint*) = nullptr;
  EGLSurface (*create_pbuffer)(EGLDisplay, EGLConfig, const EGLint*) = nullptr;
  EGLSurface (*create_window)(EGLDisplay, EGLConfig, EGLNativeWindowType, const EGLint*) = nullptr;
  EGLBoolean (*destroy_surface)(EGLDisplay, EGLSurface) = nullptr;
  EGLBoolean (*query_surface)(EGLDisplay, EGLSurface, EGLint, EGLint*) = nullptr;
  EGLBoolean (*surface_attrib)(EGLDisplay, EGLSurface, EGLint, EGLint) = nullptr;
  EGLContext (*create_context)(EGLDisplay, EGLConfig, EGLContext, const EGLint*) = nullptr;
  EGLBoolean (*destroy_context)(EGLDisplay, EGLContext) = nullptr;
  EGLBoolean (*make_current)(EGLDisplay, EGLSurface, EGLSurface, EGLContext) = nullptr;
  EGLBoolean (*query_context)(EGLDisplay, EGLContext, EGLint, EGLint*) = nullptr;
  const char* (*query_string)(EGLDisplay, EGLint) = nullptr;
  EGLBoolean (*swap_buffers)(EGLDisplay, EGLSurface) = nullptr;
  EGLBoolean (*swap_interval)(EGLDisplay, EGLint) = nullptr;
  EGLBoolean (*bind_tex_image)(EGLDisplay, EGLSurface, EGLint) = nullptr;
  EGLBoolean (*release_thread)() = nullptr;
  EGLBoolean (*wait_client)() = nullptr;
  void (*clear_color)(GLfloat, GLfloat, GLfloat, GLfloat) = nullptr;
  void (*clear)(GLbitfield) = nullptr;
  void (*read_pixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*) = nullptr;
  void (*rect)(GLfloat, GLfloat, GLfloat, GLfloat) = nullptr;
  void (*viewport)(GLint, GLint, GLsizei, GLsizei) = nullptr;
  GLenum (*gl_error)() = nullptr;
  EGLDisplay display = EGL_NO_DISPLAY;
};

template <typename F>
void find(const Vendor& v, F& f, const char* name) {
  f = reinterpret_cast<F>(v.imports.getProcAddress(name));
  fuzz_check(f != nullptr);
}

const Vendor& vendor() {
  static const Vendor v = [] {
    Vendor out;
    fuzz_check(__egl_Main(EGL_VENDOR_ABI_VERSION, &kExports, nullptr, &out.imports));
    find(out, out.get_error, "eglGetError");
    find(out, out.initialize, "eglInitialize");
    find(out, out.terminate, "eglTerminate");
    find(out, out.choose_config, "eglChooseConfig");
    find(out, out.get_configs, "eglGetConfigs");
    find(out, out.get_config_attrib, "eglGetConfigAttrib");
    find(out, out.create_pbuffer, "eglCreatePbufferSurface");
    find(out, out.create_window, "eglCreateWindowSurface");
    find(out, out.destroy_surface, "eglDestroySurface");
    find(out, out.query_surface, "eglQuerySurface");
    find(out, out.surface_attrib, "eglSurfaceAttrib");
    find(out, out.create_context, "eglCreateContext");
    find(out, out.destroy_context, "eglDestroyContext");
    find(out, out.make_current, "eglMakeCurrent");
    find(out, out.query_context, "eglQueryContext");
    find(out, out.query_string, "eglQueryString");
    find(out, out.swap_buffers, "eglSwapBuffers");
    find(out, out.swap_interval, "eglSwapInterval");
    find(out, out.bind_tex_image, "eglBindTexImage");
    find(out, out.release_thread, "eglReleaseThread");
    find(out, out.wait_client, "eglWaitClient");
    find(out, out.clear_color, "glClearColor");
    find(out, out.clear, "glClear");
    find(out, out.read_pixels, "glReadPixels");
    find(out, out.rect, "glRectf");
    find(out, out.viewport, "glViewport");
    find(out, out.gl_error, "glGetError");
    out.display = out.imports.getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, nullptr, nullptr);
    fuzz_check(out.display != EGL_NO_DISPLAY);
    fuzz_check(out.imports.getPlatformDisplay(0x31D5 /* EGL_PLATFORM_X11_KHR */, nullptr, nullptr) == EGL_NO_DISPLAY);
    return out;
  }();
  return v;
}

// The result and the error agree: EGL_SUCCESS after a success, an error after a failure.
void agree(bool ok) {
  const EGLint error = vendor().get_error();
  if (ok)
    fuzz_check(error == EGL_SUCCESS);
  else
    fuzz_check(error >= EGL_NOT_INITIALIZED && error <= EGL_CONTEXT_LOST);
  fuzz_check(vendor().get_error() == EGL_SUCCESS);
}

// An attribute list: names near EGL's (0x3020..0x3100, 0x31B0..0x31C0, 0x3098, 0x30FB,
// 0x30FC, 0x30FD, 0x3300..) and any values; sizes within 64 so that nothing big is drawn.
std::vector<EGLint> attribute_list(Bytes& in) {
  std::vector<EGLint> list;
  const int pairs = in.u8() % 12;
  for (int i = 0; i < pairs; ++i) {
    static const EGLint bases[] = {0x3020, 0x3080, 0x30C0, 0x30F0, 0x3090, 0x31B0, 0x3300, 0x0};
    const uint8_t b = in.u8();
    const EGLint name = bases[b % 8] + (in.u8() & 0x3f);
    EGLint value = in.i32();
    if (b & 0x80) value = int8_t(value);  // small values, often
    if (name == EGL_WIDTH || name == EGL_HEIGHT) value = value % 69 - 4;
    list.push_back(name);
    list.push_back(value);
  }
  if (in.u8() % 8) {
    list.push_back(EGL_NONE);
  } else {  // unterminated: the parsers must stop at their limit (kListLimit ints)
    if (list.empty()) list = {0x3300, 0};
    while (list.size() < 4096) list.push_back(list[list.size() - 2]);
  }
  return list;
}

template <typename T>
T pick(Bytes& in, const std::vector<T>& pool, T invented) {
  const uint8_t b = in.u8();
  if (pool.empty() || b % 8 == 7) return b & 8 ? invented : T{};
  return pool[b % pool.size()];
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const Vendor& v = vendor();
  Bytes in(data, size);
  static int invented_object;
  void* invented = &invented_object;
  std::vector<EGLConfig> configs;
  std::vector<EGLSurface> surfaces;
  std::vector<EGLContext> contexts;
  EGLSurface drawing = EGL_NO_SURFACE;  // the current context's surface (ours: one thread)
  for (int step = 0; step < 200 && !in.empty(); ++step) {
    const EGLDisplay dpy = in.u8() % 32 == 0 ? EGLDisplay(invented) : v.display;
    switch (in.u8() % 18) {
      case 0: agree(v.initialize(dpy, nullptr, nullptr)); break;
      case 1: agree(v.terminate(dpy)); break;  // (the handles stay in the pools: stale from now on)
      case 2: {
        const std::vector<EGLint> list = attribute_list(in);
        EGLConfig found[8];
        EGLint n = -1;
        const bool ok = v.choose_config(dpy, list.data(), found, in.u8() % 9, &n);
        agree(ok);
        if (!ok) break;
        fuzz_check(n >= 0 && n <= 8);
        for (int i = 0; i < n; ++i) configs.push_back(found[i]);
        break;
      }
      case 3: {
        EGLConfig all[8];
        EGLint n = 0;
        const bool ok = v.get_configs(dpy, all, 8, &n);
        agree(ok);
        if (ok) configs.assign(all, all + n);
        break;
      }
      case 4: {
        EGLint value = 0;
        const EGLConfig config = pick(in, configs, EGLConfig(invented));
        agree(v.get_config_attrib(dpy, config, 0x3020 + in.u8() % 0x40, &value));
        break;
      }
      case 5: {
        const std::vector<EGLint> list = attribute_list(in);
        const EGLConfig config = pick(in, configs, EGLConfig(invented));
        const EGLSurface s = v.create_pbuffer(dpy, config, list.data());
        agree(s != EGL_NO_SURFACE);
        if (s == EGL_NO_SURFACE) break;
        EGLint w = -1, h = -1;
        fuzz_check(v.query_surface(dpy, s, EGL_WIDTH, &w) && v.query_surface(dpy, s, EGL_HEIGHT, &h));
        fuzz_check(w >= 0 && w <= 64 && h >= 0 && h <= 64);
        surfaces.push_back(s);
        break;
      }
      case 6: {
        const std::vector<EGLint> list = attribute_list(in);
        g_api = in.u8() % 8 == 0 ? EGL_OPENGL_ES_API : EGL_OPENGL_API;
        const EGLConfig config = pick(in, configs, EGLConfig(invented));
        const EGLContext share = pick(in, contexts, EGLContext(invented));
        const EGLContext c = v.create_context(dpy, config, share, list.data());
        agree(c != EGL_NO_CONTEXT);
        if (c != EGL_NO_CONTEXT) contexts.push_back(c);
        break;
      }
      case 7: {
        const EGLSurface s = pick(in, surfaces, EGLSurface(invented));
        const EGLSurface r = in.u8() % 8 == 0 ? pick(in, surfaces, EGLSurface(invented)) : s;
        const EGLContext c = pick(in, contexts, EGLContext(invented));
        const bool ok = v.make_current(dpy, s, r, c);
        agree(ok);
        if (ok) drawing = s;
        break;
      }
      case 8: {  // draw and read back, if a context is current
        const float g = float(in.u8()) / 255.0f;
        v.clear_color(0, g, 0, 1);
        v.clear(GL_COLOR_BUFFER_BIT);
        const bool whole = in.u8() % 3 == 2;
        // (The viewport is the context's: empty if it was first made current without a
        // surface, EGL_KHR_surfaceless_context; one pixel is always in a pbuffer.)
        if (whole) v.viewport(0, 0, 1, 1);
        v.rect(-1, -1, whole ? 1.0f : 0.0f, 1);
        unsigned char pixel[4] = {1, 2, 3, 4};
        v.read_pixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
        // A pbuffer covered in white (GL's default colour) reads back white.
        if (drawing != EGL_NO_SURFACE && whole) fuzz_check(pixel[0] == 255 && pixel[1] == 255 && pixel[2] == 255);
        while (v.gl_error() != GL_NO_ERROR) {
        }
        break;
      }
      case 9: {
        const EGLSurface s = pick(in, surfaces, EGLSurface(invented));
        const bool ok = v.destroy_surface(dpy, s);
        agree(ok);
        break;
      }
      case 10: agree(v.destroy_context(dpy, pick(in, contexts, EGLContext(invented)))); break;
      case 11: {
        EGLint value = 0;
        const EGLSurface s = pick(in, surfaces, EGLSurface(invented));
        agree(v.query_surface(dpy, s, 0x3020 + in.u8() % 0x80, &value));
        break;
      }
      case 12: {
        EGLint value = 0;
        const EGLContext c = pick(in, contexts, EGLContext(invented));
        agree(v.query_context(dpy, c, 0x3020 + in.u8() % 0x100, &value));
        break;
      }
      case 13: {
        const EGLSurface s = pick(in, surfaces, EGLSurface(invented));
        const EGLint attribute = 0x3080 + in.u8() % 0x20;
        agree(v.surface_attrib(dpy, s, attribute, in.i32()));
        break;
      }
      case 14: {
        const bool ok = v.release_thread();
        agree(ok);
        drawing = EGL_NO_SURFACE;
        break;
      }
      case 15: {
        const EGLDisplay which = in.u8() & 1 ? dpy : EGL_NO_DISPLAY;
        const char* s = v.query_string(which, 0x3050 + in.u8() % 0x10);
        agree(s != nullptr);
        if (s) fuzz_check(std::strlen(s) < 1000);
        break;
      }
      case 16:
        switch (in.u8() % 4) {
          case 0: agree(v.swap_buffers(dpy, pick(in, surfaces, EGLSurface(invented)))); break;
          case 1: agree(v.swap_interval(dpy, in.i32())); break;
          case 2: {
            const EGLSurface s = pick(in, surfaces, EGLSurface(invented));
            agree(v.bind_tex_image(dpy, s, in.i32()));
            break;
          }
          default: agree(v.wait_client()); break;
        }
        break;
      default: agree(v.create_window(dpy, pick(in, configs, EGLConfig(invented)), 0, nullptr) != EGL_NO_SURFACE); break;
    }
  }
  // Nothing lives on into the next input: released, then terminated.
  agree(v.make_current(v.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  agree(v.terminate(v.display));
  return 0;
}
