// libEGL_velocity: pGL as a libglvnd EGL vendor (docs/gl.md, "Headless programs: the
// EGL vendor"). libglvnd's libEGL loads it from its JSON file in egl_vendor.d, calls
// __egl_Main, and from then on reaches every EGL function and every GL function through
// getProcAddress below; EGL's own bookkeeping (eglGetDisplay's choice of vendor,
// eglBindAPI, eglGetCurrentContext, eglGetProcAddress, the GL dispatch) stays in libEGL.
// The library exports nothing else and is linked -Bsymbolic, so pGL's own calls never
// go back through glvnd's stubs.
//
// What it serves: EGL 1.4 on one display, the surfaceless platform's
// (EGL_MESA_platform_surfaceless) which is also the default display; pbuffer surfaces
// and, with EGL_KHR_surfaceless_context, none (a program draws into framebuffer
// objects); desktop OpenGL 1.0-1.5 compatibility contexts (EGL_KHR_create_context). No
// native windows or pixmaps exist on it: creating one fails as that platform's
// specification says. A context is an OSMesa context drawing into its pbuffer's pixels.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <glvnd/libeglabi.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "../src/context.hpp"
#include "configs.hpp"

namespace {

using velocity::egl::Config;
using velocity::egl::kConfigCount;
using velocity::egl::kConfigs;
using velocity::egl::kListLimit;

// --- errors: the calling thread's last one (eglGetError, through libEGL) ----------------

thread_local EGLint t_error = EGL_SUCCESS;

EGLBoolean succeed() {
  t_error = EGL_SUCCESS;
  return EGL_TRUE;
}
EGLBoolean fail(EGLint error) {
  t_error = error;
  return EGL_FALSE;
}
template <typename T>
T fail(EGLint error, T result) {
  t_error = error;
  return result;
}

// --- the objects --------------------------------------------------------------------------

struct Surface {
  uint64_t serial = 0;  // its own, never reused (an address can be)
  const Config* config = nullptr;
  int width = 0, height = 0;  // as created; the pixels are at least 1x1
  bool largest = false;       // EGL_LARGEST_PBUFFER was asked for
  std::vector<unsigned char> pixels;  // RGBA, bottom row first (OSMesa's layout)
  EGLint swap_behavior = EGL_BUFFER_PRESERVED, mipmap_level = 0;
  int users = 0;        // contexts that draw into it (on their threads)
  uint64_t drawn_by = 0;  // the serial of the context that last drew into it
  bool doomed = false;  // destroyed (or terminated) while a context still draws into it
};

struct Context {
  uint64_t serial = 0;
  OSMesaContext osmesa = nullptr;
  const Config* config = nullptr;
  int major = 1;
  Surface* surface = nullptr;  // null: current without one (EGL_KHR_surfaceless_context)
  unsigned char none[4] = {0, 0, 0, 0};  // framebuffer 0 of a context without a surface
  bool current = false;  // on some thread
  bool bound_before = false;
  uint64_t drew_into = 0;  // the serial of the surface it last drew into
  bool doomed = false;   // destroyed (or terminated) while current: freed when released
};

// The one display. Its handle is its address; objects' handles are theirs, and each
// is looked up in these tables before it is used, so a stale or made-up handle is an
// error, never a dereference.
struct Display {
  std::atomic<bool> initialized{false};  // (read without the lock by every call)
  std::map<const void*, std::unique_ptr<Surface>> surfaces;
  std::map<const void*, std::unique_ptr<Context>> contexts;
};

std::mutex g_mutex;  // g_display's tables, g_serial
Display g_display;
uint64_t g_serial = 0;
thread_local Context* t_current = nullptr;
const __EGLapiExports* g_exports = nullptr;

EGLDisplay handle() { return static_cast<EGLDisplay>(&g_display); }
EGLConfig handle(const Config* c) { return const_cast<Config*>(c); }

const Config* config_from(EGLConfig config) {
  for (const Config& c : kConfigs)
    if (handle(&c) == config) return &c;
  return nullptr;
}

// The display if it is this vendor's and initialized; else null, the error set.
Display* initialized(EGLDisplay dpy) {
  if (dpy != handle()) return fail(EGL_BAD_DISPLAY, nullptr);
  if (!g_display.initialized) return fail(EGL_NOT_INITIALIZED, nullptr);
  return &g_display;
}

Surface* live_surface(EGLSurface surface) {
  auto it = g_display.surfaces.find(surface);
  return it == g_display.surfaces.end() || it->second->doomed ? nullptr : it->second.get();
}
Context* live_context(EGLContext context) {
  auto it = g_display.contexts.find(context);
  return it == g_display.contexts.end() || it->second->doomed ? nullptr : it->second.get();
}

void free_context(Context* c) {
  OSMesaDestroyContext(c->osmesa);
  g_display.contexts.erase(c);
}

// The calling thread's context lets go (its drawing finished into its surface's
// pixels), and what was destroyed meanwhile is freed.
void lose_current() {
  Context* c = t_current;
  if (!c) return;
  glFinish();
  OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  t_current = nullptr;
  std::lock_guard<std::mutex> lock(g_mutex);
  c->current = false;
  if (Surface* s = c->surface) {
    c->surface = nullptr;
    if (--s->users == 0 && s->doomed) g_display.surfaces.erase(s);
  }
  if (c->doomed) free_context(c);
}

// The context draws into the surface's pixels (none: its own 1x1 framebuffer 0).
bool bind(Context* c, Surface* s) {
  void* pixels = s ? s->pixels.data() : c->none;
  const int w = s ? std::max(1, s->width) : 1, h = s ? std::max(1, s->height) : 1;
  if (!OSMesaMakeCurrent(c->osmesa, pixels, GL_UNSIGNED_BYTE, w, h)) return false;
  velocity::gl::Context* gl = velocity::gl::current();
  // A pbuffer is EGL's back buffer: GL draws to and reads from GL_BACK, as on Mesa.
  gl->set_double_buffered(s != nullptr);
  gl->set_samples_side(c->config->samples_side);
  // A surface owns its colour buffer: one drawn since by another context, or a context
  // that drew elsewhere since, starts from the surface's pixels.
  if (s && (s->drawn_by != c->serial || c->drew_into != s->serial)) gl->load_buffer_colour();
  // (Without a surface the context draws into a 1x1 buffer, its renderer resized: what
  // it held of its last surface is gone.)
  if (s)
    s->drawn_by = c->serial, c->drew_into = s->serial;
  else
    c->drew_into = 0;
  // EGL_KHR_surfaceless_context: first made current without a surface, the viewport
  // and scissor box are empty.
  if (!s && !c->bound_before) glViewport(0, 0, 0, 0), glScissor(0, 0, 0, 0);
  c->bound_before = true;
  return true;
}

// --- displays and configurations ---------------------------------------------------------

// The surfaceless platform's display, and the default display (eglGetDisplay's
// EGL_DEFAULT_DISPLAY, which libEGL asks for with platform EGL_NONE).
EGLDisplay get_platform_display(EGLenum platform, void* native, const EGLAttrib* attributes) {
  if (platform != EGL_NONE && platform != EGL_PLATFORM_SURFACELESS_MESA) return fail(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
  if (native != nullptr) return fail(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);  // (EGL_DEFAULT_DISPLAY only)
  if (attributes && attributes[0] != EGL_NONE) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_DISPLAY);
  succeed();
  return handle();
}

EGLBoolean EGLAPIENTRY impl_Initialize(EGLDisplay dpy, EGLint* major, EGLint* minor) {
  if (dpy != handle()) return fail(EGL_BAD_DISPLAY);
  std::lock_guard<std::mutex> lock(g_mutex);
  g_display.initialized = true;
  if (major) *major = 1;
  if (minor) *minor = 4;
  return succeed();
}

// Every object goes; those still current are freed when their thread lets them go.
EGLBoolean EGLAPIENTRY impl_Terminate(EGLDisplay dpy) {
  if (dpy != handle()) return fail(EGL_BAD_DISPLAY);
  std::lock_guard<std::mutex> lock(g_mutex);
  for (auto it = g_display.contexts.begin(); it != g_display.contexts.end();) {
    Context* c = (it++)->second.get();
    if (c->current)
      c->doomed = true;
    else
      free_context(c);
  }
  for (auto it = g_display.surfaces.begin(); it != g_display.surfaces.end();) {
    Surface* s = (it++)->second.get();
    if (s->users)
      s->doomed = true;
    else
      g_display.surfaces.erase(s);
  }
  g_display.initialized = false;
  return succeed();
}

EGLBoolean give_configs(const std::vector<const Config*>& found, EGLConfig* configs, EGLint size, EGLint* count) {
  if (!count) return fail(EGL_BAD_PARAMETER);
  if (!configs) {
    *count = EGLint(found.size());
    return succeed();
  }
  const int n = std::min(int(found.size()), std::max(0, int(size)));
  for (int i = 0; i < n; ++i) configs[i] = handle(found[size_t(i)]);
  *count = n;
  return succeed();
}

EGLBoolean EGLAPIENTRY impl_GetConfigs(EGLDisplay dpy, EGLConfig* configs, EGLint size, EGLint* count) {
  if (!initialized(dpy)) return EGL_FALSE;
  std::vector<const Config*> all;
  for (const Config& c : kConfigs) all.push_back(&c);
  return give_configs(all, configs, size, count);
}

EGLBoolean EGLAPIENTRY impl_ChooseConfig(EGLDisplay dpy, const EGLint* attributes, EGLConfig* configs, EGLint size,
                                         EGLint* count) {
  if (!initialized(dpy)) return EGL_FALSE;
  EGLint error = EGL_SUCCESS;
  const std::vector<const Config*> found = velocity::egl::choose_configs(attributes, kListLimit, &error);
  if (error != EGL_SUCCESS) return fail(error);
  return give_configs(found, configs, size, count);
}

EGLBoolean EGLAPIENTRY impl_GetConfigAttrib(EGLDisplay dpy, EGLConfig config, EGLint attribute, EGLint* value) {
  if (!initialized(dpy)) return EGL_FALSE;
  const Config* c = config_from(config);
  if (!c) return fail(EGL_BAD_CONFIG);
  if (!value) return fail(EGL_BAD_PARAMETER);
  EGLint v = 0;
  if (!velocity::egl::config_attribute(*c, attribute, &v)) return fail(EGL_BAD_ATTRIBUTE);
  *value = v;
  return succeed();
}

// --- surfaces ------------------------------------------------------------------------------

// The surfaceless platform has no native windows or pixmaps: "eglCreatePlatformWindowSurface
// fails when called with a display that belongs to the surfaceless platform"
// (EGL_MESA_platform_surfaceless), whatever the configuration.
EGLSurface no_window(EGLDisplay dpy) {
  if (!initialized(dpy)) return EGL_NO_SURFACE;
  return fail(EGL_BAD_NATIVE_WINDOW, EGL_NO_SURFACE);
}
EGLSurface no_pixmap(EGLDisplay dpy) {
  if (!initialized(dpy)) return EGL_NO_SURFACE;
  return fail(EGL_BAD_NATIVE_PIXMAP, EGL_NO_SURFACE);
}
EGLSurface EGLAPIENTRY impl_CreateWindowSurface(EGLDisplay dpy, EGLConfig, EGLNativeWindowType, const EGLint*) {
  return no_window(dpy);
}
EGLSurface EGLAPIENTRY impl_CreatePlatformWindowSurface(EGLDisplay dpy, EGLConfig, void*, const EGLAttrib*) {
  return no_window(dpy);
}
EGLSurface EGLAPIENTRY impl_CreatePlatformWindowSurfaceEXT(EGLDisplay dpy, EGLConfig, void*, const EGLint*) {
  return no_window(dpy);
}
EGLSurface EGLAPIENTRY impl_CreatePixmapSurface(EGLDisplay dpy, EGLConfig, EGLNativePixmapType, const EGLint*) {
  return no_pixmap(dpy);
}
EGLSurface EGLAPIENTRY impl_CreatePlatformPixmapSurface(EGLDisplay dpy, EGLConfig, void*, const EGLAttrib*) {
  return no_pixmap(dpy);
}
EGLSurface EGLAPIENTRY impl_CreatePlatformPixmapSurfaceEXT(EGLDisplay dpy, EGLConfig, void*, const EGLint*) {
  return no_pixmap(dpy);
}

// EGL 1.4's client buffers are OpenVG images: no OpenVG here.
EGLSurface EGLAPIENTRY impl_CreatePbufferFromClientBuffer(EGLDisplay dpy, EGLenum, EGLClientBuffer, EGLConfig,
                                                          const EGLint*) {
  if (!initialized(dpy)) return EGL_NO_SURFACE;
  return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
}

EGLSurface EGLAPIENTRY impl_CreatePbufferSurface(EGLDisplay dpy, EGLConfig config, const EGLint* attributes) {
  if (!initialized(dpy)) return EGL_NO_SURFACE;
  const Config* c = config_from(config);
  if (!c) return fail(EGL_BAD_CONFIG, EGL_NO_SURFACE);
  velocity::egl::PbufferRequest request;
  if (const EGLint error = velocity::egl::parse_pbuffer_attributes(attributes, kListLimit, &request);
      error != EGL_SUCCESS)
    return fail(error, EGL_NO_SURFACE);
  auto s = std::make_unique<Surface>();
  s->config = c, s->width = request.width, s->height = request.height, s->largest = request.largest;
  try {
    s->pixels.assign(size_t(std::max(1, s->width)) * size_t(std::max(1, s->height)) * 4, 0);
  } catch (const std::exception&) {
    return fail(EGL_BAD_ALLOC, EGL_NO_SURFACE);
  }
  std::lock_guard<std::mutex> lock(g_mutex);
  s->serial = ++g_serial;
  Surface* out = s.get();
  g_display.surfaces[out] = std::move(s);
  succeed();
  return out;
}

EGLBoolean EGLAPIENTRY impl_DestroySurface(EGLDisplay dpy, EGLSurface surface) {
  if (!initialized(dpy)) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(g_mutex);
  Surface* s = live_surface(surface);
  if (!s) return fail(EGL_BAD_SURFACE);
  if (s->users)
    s->doomed = true;  // EGL: freed once no context draws into it
  else
    g_display.surfaces.erase(s);
  return succeed();
}

EGLBoolean EGLAPIENTRY impl_QuerySurface(EGLDisplay dpy, EGLSurface surface, EGLint attribute, EGLint* value) {
  if (!initialized(dpy)) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(g_mutex);
  const Surface* s = live_surface(surface);
  if (!s) return fail(EGL_BAD_SURFACE);
  if (!value) return fail(EGL_BAD_PARAMETER);
  switch (attribute) {
    case EGL_CONFIG_ID: *value = s->config->id; break;
    case EGL_WIDTH: *value = s->width; break;
    case EGL_HEIGHT: *value = s->height; break;
    case EGL_LARGEST_PBUFFER: *value = s->largest; break;
    case EGL_TEXTURE_FORMAT: case EGL_TEXTURE_TARGET: *value = EGL_NO_TEXTURE; break;
    case EGL_MIPMAP_TEXTURE: *value = EGL_FALSE; break;
    case EGL_MIPMAP_LEVEL: *value = s->mipmap_level; break;
    case EGL_RENDER_BUFFER: *value = EGL_BACK_BUFFER; break;  // a pbuffer's only buffer
    case EGL_SWAP_BEHAVIOR: *value = s->swap_behavior; break;
    case EGL_MULTISAMPLE_RESOLVE: *value = EGL_MULTISAMPLE_RESOLVE_DEFAULT; break;
    case EGL_HORIZONTAL_RESOLUTION: case EGL_VERTICAL_RESOLUTION: case EGL_PIXEL_ASPECT_RATIO:
      *value = EGL_UNKNOWN;  // no display device
      break;
    case EGL_VG_ALPHA_FORMAT: *value = EGL_VG_ALPHA_FORMAT_NONPRE; break;
    case EGL_VG_COLORSPACE: *value = EGL_VG_COLORSPACE_sRGB; break;
    default: return fail(EGL_BAD_ATTRIBUTE);
  }
  return succeed();
}

EGLBoolean EGLAPIENTRY impl_SurfaceAttrib(EGLDisplay dpy, EGLSurface surface, EGLint attribute, EGLint value) {
  if (!initialized(dpy)) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(g_mutex);
  Surface* s = live_surface(surface);
  if (!s) return fail(EGL_BAD_SURFACE);
  switch (attribute) {
    case EGL_MIPMAP_LEVEL: s->mipmap_level = value; break;  // (no texture format: no effect)
    case EGL_SWAP_BEHAVIOR:  // a pbuffer is never swapped: both hold
      if (value != EGL_BUFFER_PRESERVED && value != EGL_BUFFER_DESTROYED) return fail(EGL_BAD_PARAMETER);
      s->swap_behavior = value;
      break;
    case EGL_MULTISAMPLE_RESOLVE:
      if (value == EGL_MULTISAMPLE_RESOLVE_BOX) return fail(EGL_BAD_MATCH);  // no EGL_MULTISAMPLE_RESOLVE_BOX_BIT
      if (value != EGL_MULTISAMPLE_RESOLVE_DEFAULT) return fail(EGL_BAD_PARAMETER);
      break;
    default: return fail(EGL_BAD_ATTRIBUTE);
  }
  return succeed();
}

// No configuration binds to a texture.
EGLBoolean tex_image(EGLDisplay dpy, EGLSurface surface, EGLint buffer) {
  if (!initialized(dpy)) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(g_mutex);
  if (!live_surface(surface)) return fail(EGL_BAD_SURFACE);
  if (buffer != EGL_BACK_BUFFER) return fail(EGL_BAD_PARAMETER);
  return fail(EGL_BAD_MATCH);  // its EGL_TEXTURE_FORMAT is EGL_NO_TEXTURE
}
EGLBoolean EGLAPIENTRY impl_BindTexImage(EGLDisplay dpy, EGLSurface surface, EGLint buffer) {
  return tex_image(dpy, surface, buffer);
}
EGLBoolean EGLAPIENTRY impl_ReleaseTexImage(EGLDisplay dpy, EGLSurface surface, EGLint buffer) {
  return tex_image(dpy, surface, buffer);
}

// A pbuffer's swap has no effect (EGL 1.4, section 3.9.1); its pixels are there at
// glFinish.
EGLBoolean EGLAPIENTRY impl_SwapBuffers(EGLDisplay dpy, EGLSurface surface) {
  if (!initialized(dpy)) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(g_mutex);
  if (!live_surface(surface)) return fail(EGL_BAD_SURFACE);
  return succeed();
}

EGLBoolean EGLAPIENTRY impl_CopyBuffers(EGLDisplay dpy, EGLSurface surface, EGLNativePixmapType) {
  if (!initialized(dpy)) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(g_mutex);
  if (!live_surface(surface)) return fail(EGL_BAD_SURFACE);
  return fail(EGL_BAD_NATIVE_PIXMAP);  // no native pixmaps on this platform
}

EGLBoolean EGLAPIENTRY impl_SwapInterval(EGLDisplay dpy, EGLint) {
  if (!initialized(dpy)) return EGL_FALSE;
  if (!t_current) return fail(EGL_BAD_CONTEXT);
  if (!t_current->surface) return fail(EGL_BAD_SURFACE);
  return succeed();  // clamped to [0, 0]: nothing waits for a refresh
}

// --- contexts ------------------------------------------------------------------------------

EGLContext EGLAPIENTRY impl_CreateContext(EGLDisplay dpy, EGLConfig config, EGLContext share, const EGLint* attributes) {
  if (!initialized(dpy)) return EGL_NO_CONTEXT;
  const EGLenum api = g_exports ? g_exports->getCurrentApi() : EGL_OPENGL_API;
  if (api == EGL_NONE) return fail(EGL_BAD_MATCH, EGL_NO_CONTEXT);
  const Config* c = config_from(config);
  // OpenGL ES (eglBindAPI's default) is not what any configuration renders.
  if (!c || api != EGL_OPENGL_API) return fail(EGL_BAD_CONFIG, EGL_NO_CONTEXT);
  velocity::egl::ContextRequest request;
  if (const EGLint error = velocity::egl::check_context_attributes(attributes, kListLimit, &request);
      error != EGL_SUCCESS)
    return fail(error, EGL_NO_CONTEXT);
  std::lock_guard<std::mutex> lock(g_mutex);
  if (share != EGL_NO_CONTEXT)  // pGL shares no lists or textures between contexts (docs/gl.md)
    return fail(live_context(share) ? EGL_BAD_MATCH : EGL_BAD_CONTEXT, EGL_NO_CONTEXT);
  auto context = std::make_unique<Context>();
  // EGL names no accumulation buffer; GL 1.x programs use one: each context has a
  // 16-bit one, allocated when first used.
  context->osmesa = OSMesaCreateContextExt(OSMESA_RGBA, c->depth, c->stencil, 16, nullptr);
  if (!context->osmesa) return fail(EGL_BAD_ALLOC, EGL_NO_CONTEXT);
  context->config = c, context->major = request.major, context->serial = ++g_serial;
  Context* out = context.get();
  g_display.contexts[out] = std::move(context);
  succeed();
  return out;
}

EGLBoolean EGLAPIENTRY impl_DestroyContext(EGLDisplay dpy, EGLContext ctx) {
  if (!initialized(dpy)) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(g_mutex);
  Context* c = live_context(ctx);
  if (!c) return fail(EGL_BAD_CONTEXT);
  if (c->current)
    c->doomed = true;  // EGL: freed once no thread has it current
  else
    free_context(c);
  return succeed();
}

EGLBoolean EGLAPIENTRY impl_MakeCurrent(EGLDisplay dpy, EGLSurface draw, EGLSurface read, EGLContext ctx) {
  if (dpy != handle()) return fail(EGL_BAD_DISPLAY);
  if (ctx == EGL_NO_CONTEXT) {  // release (allowed on a terminated display too)
    if (draw != EGL_NO_SURFACE || read != EGL_NO_SURFACE) return fail(EGL_BAD_MATCH);
    lose_current();
    return succeed();
  }
  if (!initialized(dpy)) return EGL_FALSE;
  Context* c = nullptr;
  Surface* s = nullptr;
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    c = live_context(ctx);
    if (!c) return fail(EGL_BAD_CONTEXT);
    if (draw != read) return fail(EGL_BAD_MATCH);  // pGL reads where it draws
    if (draw != EGL_NO_SURFACE) {
      s = live_surface(draw);
      if (!s) return fail(EGL_BAD_SURFACE);
      // Compatible: the depth, stencil and sample buffers the context was made for.
      if (s->config->depth != c->config->depth || s->config->stencil != c->config->stencil ||
          s->config->samples_side != c->config->samples_side)
        return fail(EGL_BAD_MATCH);
    }
    if (c == t_current && c->surface == s) return succeed();
    if (c->current && c != t_current) return fail(EGL_BAD_ACCESS);  // current in another thread
    if (s && s->users && !(t_current && t_current->surface == s)) return fail(EGL_BAD_ACCESS);
    // Reserved: no other thread makes them current or frees them from here on.
    c->current = true;
    if (s) ++s->users;
  }
  if (c != t_current)
    lose_current();  // the thread's other context lets go
  else
    glFinish();  // the same context, onto another surface: its drawing into the old one first
  std::lock_guard<std::mutex> lock(g_mutex);
  if (Surface* old = c->surface) {  // (only when it moves between surfaces)
    c->surface = nullptr;
    if (--old->users == 0 && old->doomed) g_display.surfaces.erase(old);
  }
  if (!bind(c, s)) {
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    t_current = nullptr;
    c->current = false;
    if (s && --s->users == 0 && s->doomed) g_display.surfaces.erase(s);
    if (c->doomed) free_context(c);
    return fail(EGL_BAD_ALLOC);
  }
  c->surface = s;
  t_current = c;
  return succeed();
}

EGLBoolean EGLAPIENTRY impl_QueryContext(EGLDisplay dpy, EGLContext ctx, EGLint attribute, EGLint* value) {
  if (!initialized(dpy)) return EGL_FALSE;
  std::lock_guard<std::mutex> lock(g_mutex);
  const Context* c = live_context(ctx);
  if (!c) return fail(EGL_BAD_CONTEXT);
  if (!value) return fail(EGL_BAD_PARAMETER);
  switch (attribute) {
    case EGL_CONFIG_ID: *value = c->config->id; break;
    case EGL_CONTEXT_CLIENT_TYPE: *value = EGL_OPENGL_API; break;
    case EGL_CONTEXT_CLIENT_VERSION: *value = c->major; break;
    case EGL_RENDER_BUFFER: *value = c->current && c->surface ? EGL_BACK_BUFFER : EGL_NONE; break;
    default: return fail(EGL_BAD_ATTRIBUTE);
  }
  return succeed();
}

// --- the rest ------------------------------------------------------------------------------

// Client extensions (no display) and the display's.
constexpr char kClientExtensions[] = "EGL_EXT_client_extensions EGL_EXT_platform_base EGL_MESA_platform_surfaceless";
constexpr char kPlatformExtensions[] = "EGL_MESA_platform_surfaceless";
// EGL_KHR_get_all_proc_addresses: libEGL's eglGetProcAddress gives every core function.
constexpr char kDisplayExtensions[] = "EGL_KHR_create_context EGL_KHR_get_all_proc_addresses EGL_KHR_surfaceless_context";

const char* text(const char* s) {
  succeed();
  return s;
}

const char* EGLAPIENTRY impl_QueryString(EGLDisplay dpy, EGLint name) {
  if (dpy == EGL_NO_DISPLAY) return name == EGL_EXTENSIONS ? text(kClientExtensions) : fail(EGL_BAD_DISPLAY, nullptr);
  if (!initialized(dpy)) return nullptr;
  switch (name) {
    case EGL_VENDOR: return text("Velocity");
    case EGL_VERSION: return text("1.4 Velocity");
    case EGL_CLIENT_APIS: return text("OpenGL");
    case EGL_EXTENSIONS: return text(kDisplayExtensions);
    default: return fail(EGL_BAD_PARAMETER, nullptr);
  }
}

EGLBoolean EGLAPIENTRY impl_WaitClient() {
  if (t_current) glFinish();
  return succeed();
}
EGLBoolean EGLAPIENTRY impl_WaitGL() { return impl_WaitClient(); }
EGLBoolean EGLAPIENTRY impl_WaitNative(EGLint engine) {
  if (engine != EGL_CORE_NATIVE_ENGINE) return fail(EGL_BAD_PARAMETER);
  return succeed();  // no native rendering to wait for
}

EGLBoolean EGLAPIENTRY impl_ReleaseThread() {
  lose_current();
  return succeed();
}

EGLint EGLAPIENTRY impl_GetError() {
  const EGLint error = t_error;
  t_error = EGL_SUCCESS;
  return error;
}

struct Named {
  const char* name;
  void* function;
};
#define VEGL(n) {"egl" #n, reinterpret_cast<void*>(&impl_##n)}
const Named kEgl[] = {
    VEGL(Initialize), VEGL(Terminate), VEGL(GetConfigs), VEGL(ChooseConfig), VEGL(GetConfigAttrib),
    VEGL(CreateWindowSurface), VEGL(CreatePlatformWindowSurface), VEGL(CreatePlatformWindowSurfaceEXT),
    VEGL(CreatePixmapSurface), VEGL(CreatePlatformPixmapSurface), VEGL(CreatePlatformPixmapSurfaceEXT),
    VEGL(CreatePbufferSurface), VEGL(CreatePbufferFromClientBuffer), VEGL(DestroySurface), VEGL(QuerySurface),
    VEGL(SurfaceAttrib), VEGL(BindTexImage), VEGL(ReleaseTexImage), VEGL(SwapBuffers), VEGL(CopyBuffers),
    VEGL(SwapInterval), VEGL(CreateContext), VEGL(DestroyContext), VEGL(MakeCurrent), VEGL(QueryContext),
    VEGL(QueryString), VEGL(WaitClient), VEGL(WaitGL), VEGL(WaitNative), VEGL(ReleaseThread), VEGL(GetError),
};
#undef VEGL

// Every function <GL/gl.h> declares (gl_functions.inc is generated from it by CMake).
#define VGL_FUNCTION(n) {#n, reinterpret_cast<void*>(&n)},
const Named kGl[] = {
#include "gl_functions.inc"
};
#undef VGL_FUNCTION

void* get_proc_address(const char* name) {
  if (!name) return nullptr;
  for (const Named& f : kEgl)
    if (std::strcmp(f.name, name) == 0) return f.function;
  for (const Named& f : kGl)
    if (std::strcmp(f.name, name) == 0) return f.function;
  return nullptr;
}

EGLBoolean get_supports_api(EGLenum api) { return api == EGL_OPENGL_API; }

const char* get_vendor_string(int name) {
  return name == __EGL_VENDOR_STRING_PLATFORM_EXTENSIONS ? kPlatformExtensions : nullptr;
}

// No display extension functions of its own to dispatch: libEGL's cover every one it has.
void* get_dispatch_address(const char*) { return nullptr; }
void set_dispatch_index(const char*, int) {}

}  // namespace

extern "C" __attribute__((visibility("default"))) EGLBoolean __egl_Main(uint32_t version, const __EGLapiExports* exports,
                                                                       __EGLvendorInfo*, __EGLapiImports* imports) {
  if (EGL_VENDOR_ABI_GET_MAJOR_VERSION(version) != EGL_VENDOR_ABI_MAJOR_VERSION || !exports || !imports)
    return EGL_FALSE;
  g_exports = exports;
  imports->getPlatformDisplay = get_platform_display;
  imports->getSupportsAPI = get_supports_api;
  imports->getVendorString = get_vendor_string;
  imports->getProcAddress = get_proc_address;
  imports->getDispatchAddress = get_dispatch_address;
  imports->setDispatchIndex = set_dispatch_index;
  return EGL_TRUE;
}
