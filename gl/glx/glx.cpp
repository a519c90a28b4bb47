// libGLX_velocity: pGL as a libglvnd GLX vendor (docs/gl.md, "Unmodified programs").
// libglvnd's libGL/libGLX load it for __GLX_VENDOR_LIBRARY_NAME=velocity, call
// __glx_Main, and from then on reach every GLX 1.4 function and every GL function
// through getProcAddress below. The library exports nothing else and is linked
// -Bsymbolic, so pGL's own calls (glRect → glBegin, GLU) never go back through
// glvnd's stubs.
//
// A context is an OSMesa context drawing into its drawable's buffer: 32-bit BGRA,
// top row first, which is exactly a 24-bit TrueColor ZPixmap XImage's layout. A
// double-buffered window's buffer is its back buffer and the window itself the front
// one: glXSwapBuffers shows the buffer with XShmPutImage (the buffer is the shared
// memory segment: no copy), or XPutImage where MIT-SHM cannot be used. A single-
// buffered window or a pixmap is shown on glFlush, glFinish and glXWaitGL.
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cstddef>

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>
#include <glvnd/libglxabi.h>
#include <sys/ipc.h>
#include <sys/shm.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <thread>
#include <utility>
#include <vector>

#include "attributes.hpp"
#include "xlib_internal.h"
#include "pgl_bridge.h"


namespace {

using Clock = std::chrono::steady_clock;

// --- framebuffer configurations (attributes.hpp) ----------------------------------------
using velocity::glx::Config;
using velocity::glx::kConfigCount;
using velocity::glx::kConfigs;
using velocity::glx::kMaxSize;
using velocity::glx::kMaxSwapInterval;
constexpr int kListLimit = 4096;  // ints read of a program's attribute list, at most

GLXFBConfig handle(const Config* c) { return reinterpret_cast<GLXFBConfig>(const_cast<Config*>(c)); }
const Config* config_from(GLXFBConfig f) {
  for (const Config& c : kConfigs)
    if (handle(&c) == f) return &c;
  return nullptr;
}

// The screen's visuals pGL's buffer can be shown in: TrueColor, depth 24, 8 bits a
// channel in BGRX order, 32 bits a pixel. Configuration i is shown in the i-th of them
// (by visual id): each visual stands for one configuration, as GLX requires. A
// configuration without a visual of its own is for pbuffers only.
std::vector<XVisualInfo> usable_visuals(Display* dpy, int screen) {
  std::vector<XVisualInfo> out;
  if (!dpy || screen < 0 || screen >= ScreenCount(dpy)) return out;
  int formats = 0;
  bool packed32 = false;
  if (XPixmapFormatValues* f = XListPixmapFormats(dpy, &formats)) {
    for (int i = 0; i < formats; ++i)
      if (f[i].depth == 24 && f[i].bits_per_pixel == 32) packed32 = true;
    XFree(f);
  }
  if (!packed32) return out;
  XVisualInfo want{};
  want.screen = screen;
  want.depth = 24;
  want.c_class = TrueColor;
  int n = 0;
  XVisualInfo* v = XGetVisualInfo(dpy, VisualScreenMask | VisualDepthMask | VisualClassMask, &want, &n);
  for (int i = 0; i < n; ++i)
    if (v[i].red_mask == 0xff0000 && v[i].green_mask == 0xff00 && v[i].blue_mask == 0xff) out.push_back(v[i]);
  if (v) XFree(v);
  std::sort(out.begin(), out.end(), [](const XVisualInfo& a, const XVisualInfo& b) { return a.visualid < b.visualid; });
  return out;
}

VisualID visual_of(Display* dpy, int screen, const Config* c) {
  const std::vector<XVisualInfo> v = usable_visuals(dpy, screen);
  const int i = int(c - kConfigs);
  return i < int(v.size()) ? v[i].visualid : 0;
}

const Config* config_of_visual(Display* dpy, int screen, VisualID id) {
  const std::vector<XVisualInfo> v = usable_visuals(dpy, screen);
  for (int i = 0; i < int(v.size()) && i < kConfigCount; ++i)
    if (v[i].visualid == id) return &kConfigs[i];
  return nullptr;
}

// One attribute of a configuration (glXGetFBConfigAttrib, glXGetConfig).
bool config_attribute(Display* dpy, int screen, const Config& c, int attribute, int* value) {
  return velocity::glx::config_attribute(c, visual_of(dpy, screen, &c), attribute, value);
}

// --- drawables -------------------------------------------------------------------------

// The pixels of a drawable: MIT-SHM shared memory when the server can map it (then
// the XImage reads them where pGL wrote them), else ordinary memory for XPutImage.
struct Buffer {
  int width = 0, height = 0;
  unsigned char* pixels = nullptr;
  std::vector<unsigned char> heap;
  XImage* image = nullptr;
  // Where the image points (XShmCreateImage keeps its address): it moves with the buffer.
  std::unique_ptr<XShmSegmentInfo> shm;
  bool shared = false;
};

int g_trapped = 0;
int trap_errors(Display*, XErrorEvent* e) {
  g_trapped = e->error_code;
  return 0;
}
// X errors during a request whose failure is expected (a window destroyed under us,
// a server that cannot attach our shared memory) are caught, not fatal.
struct ErrorTrap {
  XErrorHandler old;
  ErrorTrap() : old(XSetErrorHandler(trap_errors)) { g_trapped = 0; }
  ~ErrorTrap() { XSetErrorHandler(old); }
};

bool shm_allowed() {
  const char* s = std::getenv("VELOCITY_GLX_SHM");  // 0: always XPutImage (tests the fallback)
  return !(s && std::strcmp(s, "0") == 0);
}

void release(Display* dpy, Buffer& b) {
  if (b.image) {
    if (b.shared) {
      XShmDetach(dpy, b.shm.get());
      XSync(dpy, False);
    }
    b.image->data = nullptr;  // the pixels are not Xlib's to free
    XDestroyImage(b.image);
    b.image = nullptr;
  }
  if (b.shared) shmdt(b.shm->shmaddr);
  b = Buffer{};
}

bool attach_shared(Display* dpy, Visual* visual, Buffer& b) {
  const size_t bytes = size_t(b.width) * b.height * 4;
  const int id = shmget(IPC_PRIVATE, bytes, IPC_CREAT | 0600);
  if (id < 0) return false;
  void* addr = shmat(id, nullptr, 0);
  if (addr == reinterpret_cast<void*>(-1)) {
    shmctl(id, IPC_RMID, nullptr);
    return false;
  }
  b.shm = std::make_unique<XShmSegmentInfo>();
  b.shm->shmid = id;
  b.shm->shmaddr = static_cast<char*>(addr);
  b.shm->readOnly = False;
  b.image = XShmCreateImage(dpy, visual, 24, ZPixmap, b.shm->shmaddr, b.shm.get(), unsigned(b.width),
                            unsigned(b.height));
  bool ok = b.image && b.image->bits_per_pixel == 32 && b.image->bytes_per_line == b.width * 4;
  if (ok) {
    ErrorTrap trap;
    ok = XShmAttach(dpy, b.shm.get()) && (XSync(dpy, False), g_trapped == 0);
  }
  shmctl(id, IPC_RMID, nullptr);  // freed once both sides have let go
  if (!ok) {
    if (b.image) b.image->data = nullptr, XDestroyImage(b.image), b.image = nullptr;
    shmdt(addr);
    b.shm.reset();
    return false;
  }
  b.shared = true;
  b.pixels = reinterpret_cast<unsigned char*>(addr);
  return true;
}

// A buffer of w×h (at least 1×1), with an image to show it in `visual` (none: pbuffer).
bool allocate(Display* dpy, Visual* visual, int w, int h, Buffer& b) {
  b.width = std::max(1, w), b.height = std::max(1, h);
  if (visual && XShmQueryExtension(dpy) && shm_allowed() && attach_shared(dpy, visual, b)) {
    b.image->byte_order = LSBFirst;
    return true;
  }
  try {
    b.heap.assign(size_t(b.width) * b.height * 4, 0);
  } catch (const std::exception&) {
    return false;
  }
  b.pixels = b.heap.data();
  if (visual) {
    b.image = XCreateImage(dpy, visual, 24, ZPixmap, 0, reinterpret_cast<char*>(b.pixels), unsigned(b.width),
                           unsigned(b.height), 32, b.width * 4);
    if (!b.image || b.image->bits_per_pixel != 32) {
      if (b.image) b.image->data = nullptr, XDestroyImage(b.image);
      b = Buffer{};
      return false;
    }
    b.image->byte_order = LSBFirst;  // the pixels are BGRA bytes whatever the server's order
  }
  return true;
}

struct Context;

struct Surface {
  enum Kind { Window, Pixmap, Pbuffer };
  Display* dpy = nullptr;
  XID id = 0;
  Kind kind = Window;
  const Config* config = nullptr;
  Visual* visual = nullptr;  // null for a pbuffer
  int width = 0, height = 0;   // the drawable's; the buffer is at least 1×1
  Buffer buffer;
  Buffer front;  // a double-buffered window's front buffer, when the program draws into it
  GC gc = nullptr;
  int interval = 0;  // swap interval: 0, as nothing here waits for a vertical retrace
  Clock::time_point last_swap{};
  unsigned long event_mask = 0;
  int users = 0;        // contexts bound to it
  bool doomed = false;  // destroyed by the program while a context still draws to it
  // A single-buffered window or a pixmap shows what was drawn at each flush.
  bool shown_on_flush() const { return kind == Pixmap || !config->double_buffer; }
};

struct Context {
  OSMesaContext osmesa = nullptr;
  const Config* config = nullptr;
  int screen = 0;
  Surface* surface = nullptr;
  bool current = false;  // on some thread
  bool doomed = false;   // destroyed while current: freed when released
};

std::mutex g_mutex;  // the tables below
std::map<std::pair<Display*, XID>, std::unique_ptr<Surface>> g_surfaces;
std::set<Context*> g_contexts;
std::set<Display*> g_hooked;  // displays whose closing frees their surfaces
thread_local Context* t_current = nullptr;
const __GLXapiExports* g_exports = nullptr;

void destroy_surface(Surface* s) {
  release(s->dpy, s->buffer);
  release(s->dpy, s->front);
  if (s->gc) XFreeGC(s->dpy, s->gc);
  g_surfaces.erase({s->dpy, s->id});
}

int close_display(Display* dpy, XExtCodes*) {
  std::lock_guard<std::mutex> lock(g_mutex);
  for (auto it = g_surfaces.begin(); it != g_surfaces.end();) {
    Surface* s = (it++)->second.get();
    if (s->dpy != dpy) continue;
    for (Context* c : g_contexts)
      if (c->surface == s) c->surface = nullptr;
    destroy_surface(s);
  }
  g_hooked.erase(dpy);
  return 0;
}

void hook_display(Display* dpy) {
  if (!g_hooked.insert(dpy).second) return;
  velocity_glx_on_close(dpy, close_display);
}

// The drawable's size from the server; false if it does not exist (any more).
bool drawable_size(Display* dpy, XID id, int* w, int* h, int* depth = nullptr) {
  Window root;
  int x, y;
  unsigned width = 0, height = 0, border, d = 0;
  ErrorTrap trap;
  const Status ok = XGetGeometry(dpy, id, &root, &x, &y, &width, &height, &border, &d);
  if (!ok || g_trapped) return false;
  *w = int(width), *h = int(height);
  if (depth) *depth = int(d);
  return true;
}

Surface* find_surface(Display* dpy, XID id) {
  auto it = g_surfaces.find({dpy, id});
  return it == g_surfaces.end() || it->second->doomed ? nullptr : it->second.get();
}

Surface* add_surface(Display* dpy, XID id, Surface::Kind kind, const Config* config, int screen) {
  auto s = std::make_unique<Surface>();
  s->dpy = dpy, s->id = id, s->kind = kind, s->config = config;
  if (kind != Surface::Pbuffer) {
    const VisualID vid = visual_of(dpy, screen, config);
    for (const XVisualInfo& v : usable_visuals(dpy, screen))
      if (v.visualid == vid || !s->visual) s->visual = v.visual;
  }
  hook_display(dpy);
  Surface* out = s.get();
  g_surfaces[{dpy, id}] = std::move(s);
  return out;
}

// Give the context its surface's pixels to draw into, at the surface's size.
bool bind(Context* c, Surface* s) {
  if (!OSMesaMakeCurrent(c->osmesa, s->buffer.pixels, GL_UNSIGNED_BYTE, s->buffer.width, s->buffer.height))
    return false;
  OSMesaPixelStore(OSMESA_Y_UP, 0);  // top row first, as the XImage
  velocity_glx_set_double_buffered(c->config->double_buffer);
  velocity_glx_set_samples_side(c->config->samples_side);
  return true;
}

// Follow the window's size (on make-current and after each swap, as Mesa's xlib
// driver): a new buffer, the current context moved onto it, then the old one freed.
bool follow_size(Surface* s) {
  int w = s->width, h = s->height;
  if (s->kind != Surface::Pbuffer && !drawable_size(s->dpy, s->id, &w, &h)) w = s->width, h = s->height;
  if (s->buffer.pixels && w == s->width && h == s->height) return true;
  const bool mine = t_current && t_current->surface == s;
  if (s->buffer.pixels && s->users > (mine ? 1 : 0)) return true;  // another thread draws in it
  Buffer fresh;
  if (!allocate(s->dpy, s->visual, w, h, fresh)) return false;
  std::swap(fresh, s->buffer);
  s->width = w, s->height = h;
  if (mine) bind(t_current, s);
  release(s->dpy, fresh);  // the old pixels
  return true;
}

void put(Surface* s, const Buffer& b) {
  if (!b.image || s->doomed) return;
  ErrorTrap trap;  // the window may be gone: nothing to show it in
  if (!s->gc) s->gc = XCreateGC(s->dpy, s->id, 0, nullptr);
  const unsigned w = unsigned(b.width), h = unsigned(b.height);
  if (b.shared)
    XShmPutImage(s->dpy, s->id, s->gc, b.image, 0, 0, 0, 0, w, h, False);
  else
    XPutImage(s->dpy, s->id, s->gc, b.image, 0, 0, 0, 0, w, h);
  // The server has read the pixels before pGL writes the next frame into them.
  XSync(s->dpy, False);
}
void show(Surface* s) { put(s, s->buffer); }

// A double-buffered window whose context draws into its front buffer (glDrawBuffer):
// what was drawn there shows at each flush, as a single-buffered window's does.
void show_front(Surface* s) {
  if (s->kind != Surface::Window || s->doomed) return;
  const int w = s->buffer.width, h = s->buffer.height;
  if (s->front.width != w || s->front.height != h) {
    release(s->dpy, s->front);
    if (!allocate(s->dpy, s->visual, w, h, s->front)) return;
  }
  if (velocity_glx_front(s->front.pixels, w, h)) put(s, s->front);
}

// glFlush, glFinish, glXWaitGL: pGL's, then a single-buffered drawable is shown.
void flush_current() {
  glFinish();
  Context* c = t_current;
  if (!c || !c->surface) return;
  std::lock_guard<std::mutex> lock(g_mutex);
  if (c->surface->shown_on_flush())
    show(c->surface);
  else
    show_front(c->surface);
}
void GLAPIENTRY gl_flush() { flush_current(); }
void GLAPIENTRY gl_finish() { flush_current(); }

void free_context(Context* c) {
  OSMesaDestroyContext(c->osmesa);
  g_contexts.erase(c);
  delete c;
}

// The thread's context lets go of its surface (and is freed if it was destroyed).
void lose_current() {
  Context* c = t_current;
  if (!c) return;
  glFinish();
  std::lock_guard<std::mutex> lock(g_mutex);
  if (c->surface && c->surface->shown_on_flush()) show(c->surface);
  OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  t_current = nullptr;
  c->current = false;
  if (Surface* s = c->surface) {
    c->surface = nullptr;
    if (--s->users == 0 && s->doomed) destroy_surface(s);
  }
  if (c->doomed) free_context(c);
}

// --- contexts ----------------------------------------------------------------------------

GLXContext new_context(Display* dpy, const Config* config, int screen, GLXContext share, unsigned char request) {
  if (share) {  // pGL shares no lists or textures between contexts (docs/gl.md)
    velocity_glx_error(dpy, BadMatch, 0, request, True);
    return nullptr;
  }
  auto c = std::make_unique<Context>();
  c->osmesa = OSMesaCreateContextExt(OSMESA_BGRA, config->depth, config->stencil, config->accum, nullptr);
  if (!c->osmesa) {
    velocity_glx_error(dpy, BadAlloc, 0, request, True);
    return nullptr;
  }
  c->config = config, c->screen = screen;
  std::lock_guard<std::mutex> lock(g_mutex);
  g_contexts.insert(c.get());
  return reinterpret_cast<GLXContext>(c.release());
}

Context* live(GLXContext ctx) {
  Context* c = reinterpret_cast<Context*>(ctx);
  return g_contexts.count(c) && !c->doomed ? c : nullptr;
}

GLXContext impl_CreateContext(Display* dpy, XVisualInfo* vis, GLXContext share, Bool) {
  const Config* config = vis ? config_of_visual(dpy, vis->screen, vis->visualid) : nullptr;
  if (!config) {
    velocity_glx_error(dpy, BadValue, vis ? vis->visualid : 0, VGLX_X_GLXCreateContext, True);
    return nullptr;
  }
  return new_context(dpy, config, vis->screen, share, VGLX_X_GLXCreateContext);
}

GLXContext impl_CreateNewContext(Display* dpy, GLXFBConfig fb, int render_type, GLXContext share, Bool) {
  const Config* config = config_from(fb);
  if (!config) {
    velocity_glx_error(dpy, VGLX_GLXBadFBConfig, 0, VGLX_X_GLXCreateNewContext, False);
    return nullptr;
  }
  if (render_type != GLX_RGBA_TYPE) {
    velocity_glx_error(dpy, BadValue, 0, VGLX_X_GLXCreateNewContext, True);
    return nullptr;
  }
  return new_context(dpy, config, DefaultScreen(dpy), share, VGLX_X_GLXCreateNewContext);
}

// GLX_ARB_create_context: compatibility contexts of the GL versions pGL implements.
GLXContext impl_CreateContextAttribsARB(Display* dpy, GLXFBConfig fb, GLXContext share, Bool direct,
                                        const int* attributes) {
  const unsigned char request = VGLX_X_GLXCreateContextAttribsARB;
  const Config* config = config_from(fb);
  if (!config) {
    velocity_glx_error(dpy, VGLX_GLXBadFBConfig, 0, request, False);
    return nullptr;
  }
  switch (velocity::glx::check_context_attributes(attributes, kListLimit)) {
    case velocity::glx::ContextError::Ok: break;
    case velocity::glx::ContextError::WrongValue: velocity_glx_error(dpy, BadValue, 0, request, True); return nullptr;
    case velocity::glx::ContextError::Unsupported: velocity_glx_error(dpy, BadMatch, 0, request, True); return nullptr;
    case velocity::glx::ContextError::WrongProfile:
      velocity_glx_error(dpy, VGLX_GLXBadProfileARB, 0, request, False);
      return nullptr;
  }
  (void)direct;
  return new_context(dpy, config, DefaultScreen(dpy), share, request);
}

void impl_DestroyContext(Display* dpy, GLXContext ctx) {
  std::lock_guard<std::mutex> lock(g_mutex);
  Context* c = live(ctx);
  if (!c) {
    velocity_glx_error(dpy, VGLX_GLXBadContext, 0, VGLX_X_GLXDestroyContext, False);
    return;
  }
  if (c->current)
    c->doomed = true;  // GLX: freed once no thread has it current
  else
    free_context(c);
}

Bool impl_MakeContextCurrent(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx) {
  if (draw != read) {  // pGL reads where it draws
    velocity_glx_error(dpy, BadMatch, draw, VGLX_X_GLXMakeContextCurrent, True);
    return False;
  }
  if (ctx && t_current == reinterpret_cast<Context*>(ctx) && t_current->surface &&
      t_current->surface->id == draw && t_current->surface->dpy == dpy)
    return True;
  lose_current();
  if (!ctx) return True;
  std::lock_guard<std::mutex> lock(g_mutex);
  Context* c = live(ctx);
  if (!c || c->current) {
    velocity_glx_error(dpy, c ? BadAccess : VGLX_GLXBadContext, 0, VGLX_X_GLXMakeContextCurrent, !!c);
    return False;
  }
  Surface* s = find_surface(dpy, draw);
  int w = 0, h = 0;
  if (!s) {  // an X window used directly, as GLX 1.2 programs do
    if (!drawable_size(dpy, draw, &w, &h)) {
      velocity_glx_error(dpy, VGLX_GLXBadDrawable, draw, VGLX_X_GLXMakeContextCurrent, False);
      return False;
    }
    s = add_surface(dpy, draw, Surface::Window, c->config, c->screen);
  }
  c->surface = s;
  ++s->users;
  t_current = c;
  c->current = true;
  if (!follow_size(s) || !bind(c, s)) {
    t_current = nullptr;
    c->current = false;
    c->surface = nullptr;
    --s->users;
    velocity_glx_error(dpy, BadAlloc, draw, VGLX_X_GLXMakeContextCurrent, True);
    return False;
  }
  return True;
}

Bool impl_MakeCurrent(Display* dpy, GLXDrawable draw, GLXContext ctx) {
  return impl_MakeContextCurrent(dpy, draw, draw, ctx);
}

void impl_SwapBuffers(Display* dpy, GLXDrawable draw) {
  Context* c = t_current;
  const bool mine = c && c->surface && c->surface->dpy == dpy && c->surface->id == draw;
  if (mine) glFinish();
  std::lock_guard<std::mutex> lock(g_mutex);
  Surface* s = find_surface(dpy, draw);
  if (!s) {
    int w, h;
    if (!drawable_size(dpy, draw, &w, &h)) velocity_glx_error(dpy, VGLX_GLXBadDrawable, draw, VGLX_X_GLXSwapBuffers, False);
    return;  // a window nothing has drawn to: nothing to show
  }
  if (!s->config->double_buffer || s->kind != Surface::Window) return;  // GLX: no effect
  if (s->interval > 0) {  // swap control: at most one frame every `interval` 60 Hz periods
    const auto next = s->last_swap + std::chrono::microseconds(16667) * s->interval;
    std::this_thread::sleep_until(next);
  }
  s->last_swap = Clock::now();
  if (mine) velocity_glx_swap_buffers();  // the front is now what the back is
  show(s);
  follow_size(s);
}

// --- visuals and configurations -------------------------------------------------------

int visual_count(Display* dpy, int screen) { return int(usable_visuals(dpy, screen).size()); }

XVisualInfo* impl_ChooseVisual(Display* dpy, int screen, int* attributes) {
  velocity::glx::Wanted w;
  if (!velocity::glx::parse_visual_attributes(attributes, kListLimit, w)) {
    velocity_glx_error(dpy, BadValue, 0, VGLX_X_GLXGetVisualConfigs, True);
    return nullptr;
  }
  const Config* best = velocity::glx::choose_visual(w, visual_count(dpy, screen));
  if (!best) return nullptr;
  XVisualInfo want{};
  want.visualid = visual_of(dpy, screen, best);
  want.screen = screen;
  int n = 0;
  return XGetVisualInfo(dpy, VisualIDMask | VisualScreenMask, &want, &n);  // the program XFrees it
}

GLXFBConfig* impl_ChooseFBConfig(Display* dpy, int screen, const int* attributes, int* count) {
  if (count) *count = 0;
  velocity::glx::Wanted w;
  if (!velocity::glx::parse_fbconfig_attributes(attributes, kListLimit, w)) {
    velocity_glx_error(dpy, BadValue, 0, VGLX_X_GLXGetFBConfigs, True);
    return nullptr;
  }
  const std::vector<const Config*> found = velocity::glx::choose_fbconfigs(w, visual_count(dpy, screen));
  if (found.empty()) return nullptr;
  auto* out = static_cast<GLXFBConfig*>(std::malloc(found.size() * sizeof(GLXFBConfig)));  // XFree'd
  if (!out) return nullptr;
  for (size_t i = 0; i < found.size(); ++i) out[i] = handle(found[i]);
  if (count) *count = int(found.size());
  return out;
}

GLXFBConfig* impl_GetFBConfigs(Display* dpy, int screen, int* count) {
  if (count) *count = 0;
  if (screen < 0 || screen >= ScreenCount(dpy)) return nullptr;
  auto* out = static_cast<GLXFBConfig*>(std::malloc(kConfigCount * sizeof(GLXFBConfig)));
  if (!out) return nullptr;
  for (int i = 0; i < kConfigCount; ++i) out[i] = handle(&kConfigs[i]);
  if (count) *count = kConfigCount;
  return out;
}

int impl_GetFBConfigAttrib(Display* dpy, GLXFBConfig fb, int attribute, int* value) {
  const Config* c = config_from(fb);
  if (!c) return GLX_BAD_ATTRIBUTE;
  if (attribute == GLX_USE_GL || attribute == GLX_RGBA) return GLX_BAD_ATTRIBUTE;  // glXGetConfig's only
  if (!value) return GLX_BAD_VALUE;
  return config_attribute(dpy, DefaultScreen(dpy), *c, attribute, value) ? Success : GLX_BAD_ATTRIBUTE;
}

int impl_GetConfig(Display* dpy, XVisualInfo* vis, int attribute, int* value) {
  if (!vis || !value) return GLX_BAD_VALUE;
  const Config* c = config_of_visual(dpy, vis->screen, vis->visualid);
  if (!c) {
    if (attribute != GLX_USE_GL) return GLX_BAD_VISUAL;
    *value = False;  // a visual without GL
    return Success;
  }
  return config_attribute(dpy, vis->screen, *c, attribute, value) ? Success : GLX_BAD_ATTRIBUTE;
}

XVisualInfo* impl_GetVisualFromFBConfig(Display* dpy, GLXFBConfig fb) {
  const Config* c = config_from(fb);
  const VisualID id = c ? visual_of(dpy, DefaultScreen(dpy), c) : 0;
  if (!id) return nullptr;
  XVisualInfo want{};
  want.visualid = id;
  int n = 0;
  return XGetVisualInfo(dpy, VisualIDMask, &want, &n);
}

// --- GLX drawables ---------------------------------------------------------------------

GLXDrawable new_drawable(Display* dpy, const Config* c, XID id, Surface::Kind kind, unsigned char request) {
  int w = 0, h = 0, depth = 0;
  if (!c || !visual_of(dpy, DefaultScreen(dpy), c)) {
    velocity_glx_error(dpy, c ? BadMatch : VGLX_GLXBadFBConfig, 0, request, !!c);
    return None;
  }
  if (!drawable_size(dpy, id, &w, &h, &depth) || depth != 24) {
    velocity_glx_error(dpy, depth ? BadMatch : (kind == Surface::Window ? BadWindow : BadPixmap), id, request, True);
    return None;
  }
  std::lock_guard<std::mutex> lock(g_mutex);
  if (Surface* old = find_surface(dpy, id)) {  // already a GLX drawable
    (void)old;
    velocity_glx_error(dpy, BadAlloc, id, request, True);
    return None;
  }
  Surface* s = add_surface(dpy, id, kind, c, DefaultScreen(dpy));
  s->width = w, s->height = h;
  return id;
}

void destroy_drawable(Display* dpy, GLXDrawable id, unsigned char error, unsigned char request) {
  std::lock_guard<std::mutex> lock(g_mutex);
  Surface* s = find_surface(dpy, id);
  if (!s) {
    velocity_glx_error(dpy, error, id, request, False);
    return;
  }
  if (s->users)
    s->doomed = true;  // freed when the last context lets go
  else
    destroy_surface(s);
}

GLXWindow impl_CreateWindow(Display* dpy, GLXFBConfig fb, Window win, const int*) {
  return new_drawable(dpy, config_from(fb), win, Surface::Window, VGLX_X_GLXCreateWindow);
}
void impl_DestroyWindow(Display* dpy, GLXWindow w) { destroy_drawable(dpy, w, VGLX_GLXBadWindow, VGLX_X_GLXDestroyWindow); }

GLXPixmap impl_CreatePixmap(Display* dpy, GLXFBConfig fb, Pixmap pixmap, const int*) {
  return new_drawable(dpy, config_from(fb), pixmap, Surface::Pixmap, VGLX_X_GLXCreatePixmap);
}
void impl_DestroyPixmap(Display* dpy, GLXPixmap p) { destroy_drawable(dpy, p, VGLX_GLXBadPixmap, VGLX_X_GLXDestroyPixmap); }

GLXPixmap impl_CreateGLXPixmap(Display* dpy, XVisualInfo* vis, Pixmap pixmap) {
  const Config* c = vis ? config_of_visual(dpy, vis->screen, vis->visualid) : nullptr;
  if (!c) {
    velocity_glx_error(dpy, BadValue, vis ? vis->visualid : 0, VGLX_X_GLXCreateGLXPixmap, True);
    return None;
  }
  return new_drawable(dpy, c, pixmap, Surface::Pixmap, VGLX_X_GLXCreateGLXPixmap);
}
void impl_DestroyGLXPixmap(Display* dpy, GLXPixmap p) {
  destroy_drawable(dpy, p, VGLX_GLXBadPixmap, VGLX_X_GLXDestroyGLXPixmap);
}

GLXPbuffer impl_CreatePbuffer(Display* dpy, GLXFBConfig fb, const int* attributes) {
  const Config* c = config_from(fb);
  if (!c) {
    velocity_glx_error(dpy, VGLX_GLXBadFBConfig, 0, VGLX_X_GLXCreatePbuffer, False);
    return None;
  }
  velocity::glx::PbufferSize size;
  switch (velocity::glx::parse_pbuffer_attributes(attributes, kListLimit, size)) {
    case velocity::glx::PbufferError::Ok: break;
    case velocity::glx::PbufferError::WrongValue:
      velocity_glx_error(dpy, BadValue, 0, VGLX_X_GLXCreatePbuffer, True);
      return None;
    case velocity::glx::PbufferError::TooLarge:
      velocity_glx_error(dpy, BadAlloc, 0, VGLX_X_GLXCreatePbuffer, True);
      return None;
  }
  const int w = size.width, h = size.height;
  std::lock_guard<std::mutex> lock(g_mutex);
  const XID id = XAllocID(dpy);
  Surface* s = add_surface(dpy, id, Surface::Pbuffer, c, DefaultScreen(dpy));
  s->width = w, s->height = h;
  return id;
}
void impl_DestroyPbuffer(Display* dpy, GLXPbuffer p) { destroy_drawable(dpy, p, VGLX_GLXBadPbuffer, VGLX_X_GLXDestroyPbuffer); }

void impl_QueryDrawable(Display* dpy, GLXDrawable draw, int attribute, unsigned int* value) {
  if (!value) return;
  std::lock_guard<std::mutex> lock(g_mutex);
  Surface* s = find_surface(dpy, draw);
  int w = 0, h = 0;
  if (!s && !drawable_size(dpy, draw, &w, &h)) {
    velocity_glx_error(dpy, VGLX_GLXBadDrawable, draw, VGLX_X_GLXGetDrawableAttributes, False);
    return;
  }
  if (s && s->kind != Surface::Pbuffer && !drawable_size(dpy, draw, &w, &h)) w = s->width, h = s->height;
  if (s && s->kind == Surface::Pbuffer) w = s->width, h = s->height;
  switch (attribute) {
    case GLX_WIDTH: *value = unsigned(w); break;
    case GLX_HEIGHT: *value = unsigned(h); break;
    case GLX_PRESERVED_CONTENTS: *value = True; break;
    case GLX_LARGEST_PBUFFER: *value = False; break;
    case GLX_FBCONFIG_ID: *value = s ? unsigned(s->config->id) : 0; break;
    case GLX_SWAP_INTERVAL_EXT: *value = s ? unsigned(s->interval) : 0; break;
    case GLX_MAX_SWAP_INTERVAL_EXT: *value = kMaxSwapInterval; break;
    default: velocity_glx_error(dpy, BadValue, 0, VGLX_X_GLXGetDrawableAttributes, True); break;
  }
}

void impl_SelectEvent(Display* dpy, GLXDrawable draw, unsigned long mask) {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (Surface* s = find_surface(dpy, draw))
    s->event_mask = mask;  // pbuffers are never clobbered: no event is ever sent
  else
    velocity_glx_error(dpy, VGLX_GLXBadDrawable, draw, VGLX_X_GLXChangeDrawableAttributes, False);
}

void impl_GetSelectedEvent(Display* dpy, GLXDrawable draw, unsigned long* mask) {
  std::lock_guard<std::mutex> lock(g_mutex);
  Surface* s = find_surface(dpy, draw);
  if (!s) velocity_glx_error(dpy, VGLX_GLXBadDrawable, draw, VGLX_X_GLXGetDrawableAttributes, False);
  if (mask) *mask = s ? s->event_mask : 0;
}

int impl_QueryContext(Display* dpy, GLXContext ctx, int attribute, int* value) {
  std::lock_guard<std::mutex> lock(g_mutex);
  Context* c = live(ctx);
  if (!c) return GLX_BAD_CONTEXT;
  if (!value) return GLX_BAD_VALUE;
  switch (attribute) {
    case GLX_FBCONFIG_ID: *value = c->config->id; return Success;
    case GLX_RENDER_TYPE: *value = GLX_RGBA_TYPE; return Success;
    case GLX_SCREEN: *value = c->screen; return Success;
    default: (void)dpy; return GLX_BAD_ATTRIBUTE;
  }
}

Bool impl_IsDirect(Display*, GLXContext) { return True; }

// glXCopyContext would copy state by glPushAttrib's groups, which pGL lacks.
void impl_CopyContext(Display* dpy, GLXContext, GLXContext, unsigned long) {
  velocity_glx_error(dpy, BadMatch, 0, VGLX_X_GLXCopyContext, True);
}

// glXUseXFont makes display lists of glBitmap calls; pGL has no glBitmap yet.
void impl_UseXFont(Font, int, int, int) {
  velocity_glx_gl_error(GL_INVALID_OPERATION);
}

void impl_WaitGL() { flush_current(); }
void impl_WaitX() {
  Context* c = t_current;
  if (c && c->surface) XSync(c->surface->dpy, False);
}

constexpr char kExtensions[] =
    "GLX_ARB_create_context GLX_ARB_get_proc_address GLX_EXT_swap_control GLX_MESA_swap_control "
    "GLX_SGI_swap_control "
    "GLX_ARB_multisample";  // (the GLX attributes; attributes.hpp)

const char* glx_string(int name) {
  switch (name) {
    case GLX_VENDOR: return "Velocity";
    case GLX_VERSION: return "1.4";
    case GLX_EXTENSIONS: return kExtensions;
    default: return nullptr;
  }
}
const char* impl_QueryServerString(Display*, int, int name) { return glx_string(name); }
const char* impl_GetClientString(Display*, int name) { return glx_string(name); }
const char* impl_QueryExtensionsString(Display*, int) { return kExtensions; }

// --- swap control ----------------------------------------------------------------------

void impl_SwapIntervalEXT(Display* dpy, GLXDrawable draw, int interval) {
  if (interval < 0 || interval > kMaxSwapInterval) {
    velocity_glx_error(dpy, BadValue, 0, VGLX_X_GLXChangeDrawableAttributes, True);
    return;
  }
  std::lock_guard<std::mutex> lock(g_mutex);
  Surface* s = find_surface(dpy, draw);
  if (!s) {
    int w, h;
    if (!drawable_size(dpy, draw, &w, &h)) {
      velocity_glx_error(dpy, VGLX_GLXBadDrawable, draw, VGLX_X_GLXChangeDrawableAttributes, False);
      return;
    }
    s = add_surface(dpy, draw, Surface::Window, &kConfigs[0], DefaultScreen(dpy));
  }
  s->interval = interval;
}

int impl_SwapIntervalMESA(unsigned int interval) {
  Context* c = t_current;
  if (!c || !c->surface) return GLX_BAD_CONTEXT;
  if (interval > unsigned(kMaxSwapInterval)) return GLX_BAD_VALUE;
  std::lock_guard<std::mutex> lock(g_mutex);
  c->surface->interval = int(interval);
  return 0;
}
int impl_GetSwapIntervalMESA() {
  Context* c = t_current;
  return c && c->surface ? c->surface->interval : 0;
}
int impl_SwapIntervalSGI(int interval) {
  if (interval <= 0) return GLX_BAD_VALUE;  // GLX_SGI_swap_control cannot turn it off
  return impl_SwapIntervalMESA(unsigned(interval));
}

// --- glvnd's dispatch of the GLX extension functions -------------------------------------
// libGLX hands a program these for glXGetProcAddress; each finds the vendor of its
// object and calls that vendor's function, fetched by the index libGLX gave it.

enum Extension { kCreateContextAttribs, kSwapIntervalEXT, kSwapIntervalMESA, kGetSwapIntervalMESA,
                 kSwapIntervalSGI, kExtensionCount };
int g_index[kExtensionCount] = {-1, -1, -1, -1, -1};

template <typename F>
F fetch(__GLXvendorInfo* vendor, Extension e) {
  if (!vendor || g_index[e] < 0) return nullptr;
  return reinterpret_cast<F>(g_exports->fetchDispatchEntry(vendor, g_index[e]));
}

GLXContext dispatch_CreateContextAttribsARB(Display* dpy, GLXFBConfig fb, GLXContext share, Bool direct,
                                            const int* attributes) {
  __GLXvendorInfo* vendor = fb ? g_exports->vendorFromFBConfig(dpy, fb) : g_exports->getDynDispatch(dpy, DefaultScreen(dpy));
  auto f = fetch<decltype(&impl_CreateContextAttribsARB)>(vendor, kCreateContextAttribs);
  if (!f) {
    velocity_glx_error(dpy, VGLX_GLXBadFBConfig, 0, VGLX_X_GLXCreateContextAttribsARB, False);
    return nullptr;
  }
  GLXContext ctx = f(dpy, fb, share, direct, attributes);
  if (ctx && g_exports->addVendorContextMapping(dpy, ctx, vendor) != 0) {
    impl_DestroyContext(dpy, ctx);
    velocity_glx_error(dpy, BadAlloc, 0, VGLX_X_GLXCreateContextAttribsARB, True);
    return nullptr;
  }
  return ctx;
}

void dispatch_SwapIntervalEXT(Display* dpy, GLXDrawable draw, int interval) {
  auto f = fetch<decltype(&impl_SwapIntervalEXT)>(g_exports->vendorFromDrawable(dpy, draw), kSwapIntervalEXT);
  if (f) f(dpy, draw, interval);
}
int dispatch_SwapIntervalMESA(unsigned int interval) {
  auto f = fetch<decltype(&impl_SwapIntervalMESA)>(g_exports->getCurrentDynDispatch(), kSwapIntervalMESA);
  return f ? f(interval) : GLX_BAD_CONTEXT;
}
int dispatch_GetSwapIntervalMESA() {
  auto f = fetch<decltype(&impl_GetSwapIntervalMESA)>(g_exports->getCurrentDynDispatch(), kGetSwapIntervalMESA);
  return f ? f() : 0;
}
int dispatch_SwapIntervalSGI(int interval) {
  auto f = fetch<decltype(&impl_SwapIntervalSGI)>(g_exports->getCurrentDynDispatch(), kSwapIntervalSGI);
  return f ? f(interval) : GLX_BAD_CONTEXT;
}

struct Named {
  const char* name;
  void* function;
};
#define VGLX(n) {"glX" #n, reinterpret_cast<void*>(&impl_##n)}
const Named kGlx[] = {
    VGLX(ChooseVisual), VGLX(CopyContext), VGLX(CreateContext), VGLX(CreateGLXPixmap), VGLX(DestroyContext),
    VGLX(DestroyGLXPixmap), VGLX(GetConfig), VGLX(IsDirect), VGLX(MakeCurrent), VGLX(SwapBuffers),
    VGLX(UseXFont), VGLX(WaitGL), VGLX(WaitX), VGLX(QueryServerString), VGLX(GetClientString),
    VGLX(QueryExtensionsString), VGLX(ChooseFBConfig), VGLX(CreateNewContext), VGLX(CreatePbuffer),
    VGLX(CreatePixmap), VGLX(CreateWindow), VGLX(DestroyPbuffer), VGLX(DestroyPixmap), VGLX(DestroyWindow),
    VGLX(GetFBConfigAttrib), VGLX(GetFBConfigs), VGLX(GetSelectedEvent), VGLX(GetVisualFromFBConfig),
    VGLX(MakeContextCurrent), VGLX(QueryContext), VGLX(QueryDrawable), VGLX(SelectEvent),
    VGLX(CreateContextAttribsARB), VGLX(SwapIntervalEXT), VGLX(SwapIntervalMESA), VGLX(GetSwapIntervalMESA),
    VGLX(SwapIntervalSGI),
};
#undef VGLX

struct Dispatched {
  const char* name;
  void* function;
  Extension index;
};
#define VDISPATCH(n, e) {"glX" #n, reinterpret_cast<void*>(&dispatch_##n), e}
const Dispatched kDispatched[] = {
    VDISPATCH(CreateContextAttribsARB, kCreateContextAttribs), VDISPATCH(SwapIntervalEXT, kSwapIntervalEXT),
    VDISPATCH(SwapIntervalMESA, kSwapIntervalMESA), VDISPATCH(GetSwapIntervalMESA, kGetSwapIntervalMESA),
    VDISPATCH(SwapIntervalSGI, kSwapIntervalSGI),
};
#undef VDISPATCH

// Every function <GL/gl.h> declares (gl_functions.inc is generated from it by CMake),
// glFlush and glFinish with the showing of single-buffered drawables added.
#define VGL_FUNCTION(n) {#n, reinterpret_cast<void*>(&n)},
const Named kGl[] = {
#include "gl_functions.inc"
};
#undef VGL_FUNCTION

void* get_proc_address(const GLubyte* name_bytes) {
  const char* name = reinterpret_cast<const char*>(name_bytes);
  if (!name) return nullptr;
  if (std::strcmp(name, "glFlush") == 0) return reinterpret_cast<void*>(&gl_flush);
  if (std::strcmp(name, "glFinish") == 0) return reinterpret_cast<void*>(&gl_finish);
  for (const Named& f : kGlx)
    if (std::strcmp(f.name, name) == 0) return f.function;
  for (const Named& f : kGl)
    if (std::strcmp(f.name, name) == 0) return f.function;
  return nullptr;
}

void* get_dispatch_address(const GLubyte* name) {
  for (const Dispatched& d : kDispatched)
    if (std::strcmp(d.name, reinterpret_cast<const char*>(name)) == 0) return d.function;
  return nullptr;
}

void set_dispatch_index(const GLubyte* name, int index) {
  for (const Dispatched& d : kDispatched)
    if (std::strcmp(d.name, reinterpret_cast<const char*>(name)) == 0) g_index[d.index] = index;
}

Bool is_screen_supported(Display* dpy, int screen) { return !usable_visuals(dpy, screen).empty(); }

}  // namespace

extern "C" __attribute__((visibility("default"))) Bool __glx_Main(uint32_t version, const __GLXapiExports* exports,
                                                                 __GLXvendorInfo*, __GLXapiImports* imports) {
  // ABI 1.x: the imports this library fills in are the same in every minor version.
  if (GLX_VENDOR_ABI_GET_MAJOR_VERSION(version) != GLX_VENDOR_ABI_MAJOR_VERSION || !exports || !imports)
    return False;
  g_exports = exports;
  imports->isScreenSupported = is_screen_supported;
  imports->getProcAddress = get_proc_address;
  imports->getDispatchAddress = get_dispatch_address;
  imports->setDispatchIndex = set_dispatch_index;
  return True;
}
