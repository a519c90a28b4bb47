// GLUT for pGL (<GL/glut.h>): one window on Velocity's SDL2 presenter, whose pixels are
// an OSMesa buffer that pGL renders into, and GLUT's callbacks driven from the
// presenter's events (or a script's), timers and the idle function.
//
// The loop, one turn at a time: events -> their callbacks; due timers; then the display
// callback if a redisplay was posted, else the idle callback. glutSwapBuffers (or, for a
// single-buffered window, the end of the display callback) finishes the GL frame and
// hands it to the presenter, which shows it with vertical sync.
//
// Misuse follows freeglut: a function that needs a window, called before
// glutCreateWindow, prints what was wrong and ends the program (exit(1)); so does a
// window that cannot be opened (no display). SIGINT and SIGTERM end the program as they
// end freeglut's (which installs no handler for them): SDL's handlers, which would make
// them a quit event that only the main loop sees, are taken out again.
//
// A program may never return to the main loop (a display callback that loops, calling
// glutSwapBuffers or glutPostRedisplay): VELOCITY_GLUT_FRAMES counts its frames all the
// same, and ends the program when the loop cannot be left (end_if_past_limit).
#include <GL/glut.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "menu.hpp"
#include "runtime/input.hpp"
#include "runtime/script.hpp"
#include "sdl/presenter.hpp"
#include "velocity/error.hpp"
#include "velocity/image.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using velocity::realtime::InputEvent;
using velocity::realtime::Key;

struct Timer {
  Clock::time_point due;
  unsigned long order;  // timers due at the same time fire in the order they were set
  void (*callback)(int);
  int value;
};

struct Glut {
  bool initialised = false;
  Clock::time_point start = Clock::now();
  unsigned int display_mode = GLUT_RGB | GLUT_SINGLE;
  int init_width = 300, init_height = 300;  // GLUT's defaults
  int init_x = -1, init_y = -1;

  // The window (one).
  std::unique_ptr<velocity::present::SdlPresenter> window;
  OSMesaContext context = nullptr;
  std::vector<uint8_t> pixels;  // RGBA8, top row first
  std::vector<uint8_t> overlaid;  // the pixels with the open menus drawn over them
  int width = 0, height = 0;
  bool double_buffered = false;

  void (*display)() = nullptr;
  void (*reshape)(int, int) = nullptr;
  void (*keyboard)(unsigned char, int, int) = nullptr;
  void (*keyboard_up)(unsigned char, int, int) = nullptr;
  void (*special)(int, int, int) = nullptr;
  void (*special_up)(int, int, int) = nullptr;
  void (*mouse)(int, int, int, int) = nullptr;
  void (*motion)(int, int) = nullptr;
  void (*passive_motion)(int, int) = nullptr;
  void (*idle)() = nullptr;
  std::vector<Timer> timers;
  unsigned long timer_order = 0;

  bool redisplay = true;  // the first turn draws
  bool reshape_pending = true;
  bool leave = false;
  velocity::realtime::InputState input;
  int modifiers = 0;  // during an input callback (glutGetModifiers)

  // Automation (environment variables; see glut.h).
  std::optional<velocity::realtime::ScriptPlayer> script;
  long max_frames = 0;
  std::string record_dir;
  long record_limit = 0;  // frames recorded at most
  long frames = 0;
  bool in_main_loop = false, in_display = false;
  int posts_in_display = 0;  // glutPostRedisplay calls during this display callback
  long frames_at_post = 0;   // `frames` at the last of them
};

// VELOCITY_GLUT_RECORD's bound without VELOCITY_GLUT_FRAMES (with it, that many).
constexpr long kMaxRecordedFrames = 1000;

// Never destroyed: GLUT programs end with exit() from inside the main loop, and the
// window must outlive everything that may still run then.
Glut& glut() {
  static Glut* g = new Glut;
  return *g;
}

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "velocity-glut: %s\n", message.c_str());
  std::exit(1);
}

Glut& need_window(const char* function) {
  Glut& g = glut();
  if (!g.initialised) fail(std::string(function) + " called without first calling glutInit");
  if (!g.window) fail(std::string(function) + " called with no window (glutCreateWindow first)");
  return g;
}

Glut& need_init(const char* function) {
  Glut& g = glut();
  if (!g.initialised) fail(std::string(function) + " called without first calling glutInit");
  return g;
}

long elapsed_ms(const Glut& g) {
  return long(std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - g.start).count());
}

// Sizes the OSMesa buffer to the window and makes it current (top row first: what the
// presenter shows).
void bind_buffer(Glut& g, int w, int h) {
  w = std::clamp(w, 1, 16384), h = std::clamp(h, 1, 16384);
  g.width = w, g.height = h;
  g.pixels.assign(size_t(w) * size_t(h) * 4, 0);
  if (!OSMesaMakeCurrent(g.context, g.pixels.data(), GL_UNSIGNED_BYTE, w, h)) fail("cannot bind the window's buffer");
  OSMesaPixelStore(OSMESA_Y_UP, 0);
}

void release_context() {
  Glut& g = glut();
  if (g.context) OSMesaDestroyContext(g.context);
  g.context = nullptr;
}

void release_window() {
  release_context();
  glut().window.reset();
}

// At exit (GLUT programs end with exit(), from a callback or when the window closes):
// the GL context goes, with the renderer's threads; the window is left to the end of
// the process, as GLUT leaves it (closing SDL here would unload the display's
// libraries while their own exit handlers may still run).
void at_exit() { release_context(); }

// One frame more, wherever it comes from (a swap, a single-buffered display callback's
// end, a display callback's repeated glutPostRedisplay): the last of
// VELOCITY_GLUT_FRAMES asks the main loop to stop.
void count_frame(Glut& g) {
  ++g.frames;
  if (g.max_frames > 0 && g.frames >= g.max_frames) g.leave = true;
}

// Called by a callback about to make a frame: past VELOCITY_GLUT_FRAMES, the main loop
// was asked to stop and the callback went on without returning to it (a display
// callback that loops): the program ends here (exit 0, as when its window closes)
// rather than run on.
void end_if_past_limit(const Glut& g) {
  if (!g.in_main_loop || g.max_frames == 0 || g.frames < g.max_frames) return;
  std::fflush(stdout);
  std::fprintf(stderr, "velocity-glut: %ld frames shown (VELOCITY_GLUT_FRAMES) and the program does not return "
               "to the main loop: it ends\n", g.max_frames);
  std::exit(0);
}

// The frame as shown: pGL's pixels, with the open menus drawn over a copy.
const std::vector<uint8_t>& shown(Glut& g) {
  if (!velocity::glut::menu_open()) return g.pixels;
  g.overlaid = g.pixels;
  velocity::glut::menu_overlay(g.overlaid, g.width, g.height);
  return g.overlaid;
}

void show_frame(Glut& g) {
  glFinish();
  const std::vector<uint8_t>& pixels = shown(g);
  g.window->present(pixels.data(), g.width, g.height);
  if (!g.record_dir.empty() && g.frames == g.record_limit && g.max_frames == 0)
    std::fprintf(stderr, "velocity-glut: VELOCITY_GLUT_RECORD: %ld frames recorded, no more (VELOCITY_GLUT_FRAMES "
                 "sets how many)\n", g.record_limit);
  if (!g.record_dir.empty() && g.frames < g.record_limit) {
    velocity::Image image(g.width, g.height);
    std::copy(pixels.begin(), pixels.end(), image.pixels.begin());
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05ld.png", g.frames);
    try {
      velocity::write_png((std::filesystem::path(g.record_dir) / name).string(), image);
    } catch (const velocity::Error& e) {
      fail(e.what());
    }
  }
  count_frame(g);
}

// GLUT's special keys for the presenter's, or 0 for none.
int special_key(int key) {
  if (key >= velocity::realtime::KeyF1 && key <= velocity::realtime::KeyF12) return GLUT_KEY_F1 + (key - velocity::realtime::KeyF1);
  switch (key) {
    case velocity::realtime::KeyLeft: return GLUT_KEY_LEFT;
    case velocity::realtime::KeyRight: return GLUT_KEY_RIGHT;
    case velocity::realtime::KeyUp: return GLUT_KEY_UP;
    case velocity::realtime::KeyDown: return GLUT_KEY_DOWN;
    case velocity::realtime::KeyPageUp: return GLUT_KEY_PAGE_UP;
    case velocity::realtime::KeyPageDown: return GLUT_KEY_PAGE_DOWN;
    default: return 0;
  }
}

int glut_button(velocity::realtime::MouseButton b) {
  switch (b) {
    case velocity::realtime::MouseButton::Middle: return GLUT_MIDDLE_BUTTON;
    case velocity::realtime::MouseButton::Right: return GLUT_RIGHT_BUTTON;
    default: return GLUT_LEFT_BUTTON;
  }
}

void dispatch(Glut& g, const InputEvent& e) {
  g.input.apply(e);
  g.modifiers = (g.input.held(velocity::realtime::KeyShift) ? GLUT_ACTIVE_SHIFT : 0) |
                (g.input.held(velocity::realtime::KeyCtrl) ? GLUT_ACTIVE_CTRL : 0);
  const int mx = g.input.mouse_x() < 0 ? 0 : g.input.mouse_x(), my = g.input.mouse_y() < 0 ? 0 : g.input.mouse_y();
  if ((e.kind == InputEvent::MouseDown || e.kind == InputEvent::MouseUp || e.kind == InputEvent::MouseMove) &&
      velocity::glut::menu_event(e, g.width, g.height)) {
    g.modifiers = 0;
    return;  // a menu's (menu.cpp)
  }
  switch (e.kind) {
    case InputEvent::KeyDown:
    case InputEvent::KeyUp: {
      const bool down = e.kind == InputEvent::KeyDown;
      if (const int s = special_key(e.key)) {
        if (auto f = down ? g.special : g.special_up) f(s, mx, my);
      } else if (e.key > 0 && e.key < 128) {
        int c = e.key;
        if ((g.modifiers & GLUT_ACTIVE_SHIFT) && c >= 'a' && c <= 'z') c -= 'a' - 'A';
        if ((g.modifiers & GLUT_ACTIVE_CTRL) && c >= 'a' && c <= 'z') c -= 'a' - 1;  // as GLUT: Ctrl+A is 1
        if (auto f = down ? g.keyboard : g.keyboard_up) f((unsigned char)c, mx, my);
      }
      break;
    }
    case InputEvent::MouseDown:
    case InputEvent::MouseUp:
      if (g.mouse) g.mouse(glut_button(e.button), e.kind == InputEvent::MouseDown ? GLUT_DOWN : GLUT_UP, e.x, e.y);
      break;
    case InputEvent::MouseMove: {
      const bool dragging = g.input.button(velocity::realtime::MouseButton::Left) ||
                            g.input.button(velocity::realtime::MouseButton::Middle) ||
                            g.input.button(velocity::realtime::MouseButton::Right);
      if (auto f = dragging ? g.motion : g.passive_motion) f(e.x, e.y);
      break;
    }
    case InputEvent::Resize:
      if (e.x > 0 && e.y > 0 && (e.x != g.width || e.y != g.height)) {
        bind_buffer(g, e.x, e.y);
        g.reshape_pending = true;
      }
      break;
    case InputEvent::Quit:
      // GLUT ends the program when its window is closed.
      std::fflush(stdout);
      std::exit(0);
    default: break;  // wheel and dropped files: no GLUT 3 callback
  }
  g.modifiers = 0;
}

void fire_timers(Glut& g) {
  const Clock::time_point now = Clock::now();
  // Take the due ones first: a callback may set new timers.
  std::vector<Timer> due;
  for (auto it = g.timers.begin(); it != g.timers.end();) {
    if (it->due <= now) {
      due.push_back(*it);
      it = g.timers.erase(it);
    } else {
      ++it;
    }
  }
  std::sort(due.begin(), due.end(), [](const Timer& a, const Timer& b) {
    return a.due != b.due ? a.due < b.due : a.order < b.order;
  });
  for (const Timer& t : due) t.callback(t.value);
}

}  // namespace

extern "C" {

void glutInit(int* argcp, char** argv) {
  (void)argcp, (void)argv;  // X11 options (-display, -geometry) are not read
  Glut& g = glut();
  if (g.initialised) fail("glutInit called twice");
  g.initialised = true;
  g.start = Clock::now();
  if (const char* s = std::getenv("VELOCITY_GLUT_SCRIPT"); s && *s) {
    try {
      g.script.emplace(velocity::realtime::load_script(s));
    } catch (const velocity::Error& e) {
      fail(e.what());
    }
  }
  if (const char* s = std::getenv("VELOCITY_GLUT_FRAMES"); s && *s) {
    char* end = nullptr;
    const long n = std::strtol(s, &end, 10);
    if (*end || n < 1) fail(std::string("VELOCITY_GLUT_FRAMES must be a whole number of frames >= 1, got '") + s + "'");
    g.max_frames = n;
  }
  if (const char* s = std::getenv("VELOCITY_GLUT_RECORD"); s && *s) {
    std::error_code ec;
    std::filesystem::create_directories(s, ec);
    if (ec) fail(std::string("VELOCITY_GLUT_RECORD: cannot create ") + s + ": " + ec.message());
    g.record_dir = s;
    g.record_limit = g.max_frames > 0 ? g.max_frames : kMaxRecordedFrames;
  }
}

void glutInitDisplayMode(unsigned int mode) { glut().display_mode = mode; }

void glutInitWindowSize(int width, int height) {
  if (width > 0 && height > 0) glut().init_width = width, glut().init_height = height;
}

void glutInitWindowPosition(int x, int y) { glut().init_x = x, glut().init_y = y; }

int glutCreateWindow(const char* title) {
  Glut& g = need_init("glutCreateWindow");
  if (g.window) fail("glutCreateWindow: this GLUT has one window, and it is open");
  velocity::present::WindowOptions options;
  options.title = title ? title : "";
  options.width = std::clamp(g.init_width, 1, 16384), options.height = std::clamp(g.init_height, 1, 16384);
  options.at_origin = g.init_x == 0 && g.init_y == 0;
  // SDL turns SIGINT and SIGTERM into a quit event when their action is the default;
  // the actions they had are put back, so that they end the program wherever it is
  // (a callback that never returns included), as they end freeglut's: by the signal
  // (a shell's status 128 + the signal's number).
  struct sigaction sigint_action {}, sigterm_action {};
  sigaction(SIGINT, nullptr, &sigint_action);
  sigaction(SIGTERM, nullptr, &sigterm_action);
  try {
    g.window = std::make_unique<velocity::present::SdlPresenter>(options);
  } catch (const velocity::Error& e) {
    fail(std::string("cannot open a window: ") + e.what());
  }
  sigaction(SIGINT, &sigint_action, nullptr);
  sigaction(SIGTERM, &sigterm_action, nullptr);
  g.double_buffered = g.display_mode & GLUT_DOUBLE;
  g.context = OSMesaCreateContextExt(OSMESA_RGBA, (g.display_mode & GLUT_DEPTH) ? 24 : 0,
                                     (g.display_mode & GLUT_STENCIL) ? 8 : 0,
                                     (g.display_mode & GLUT_ACCUM) ? 16 : 0, nullptr);
  if (!g.context) fail("cannot create the GL context");
  std::atexit(at_exit);  // after the GL library's own state exists: it runs first
  bind_buffer(g, options.width, options.height);
  return 1;
}

void glutDestroyWindow(int window) {
  need_window("glutDestroyWindow");
  if (window != 1) return;
  release_window();
}

int glutGetWindow(void) { return glut().window ? 1 : 0; }

void glutSetWindowTitle(const char* title) { need_window("glutSetWindowTitle").window->set_title(title ? title : ""); }

void glutReshapeWindow(int width, int height) {
  Glut& g = need_window("glutReshapeWindow");
  if (width < 1 || height < 1) return;
  bind_buffer(g, width, height);
  g.reshape_pending = true;
}

void glutFullScreen(void) { need_window("glutFullScreen").window->toggle_fullscreen(); }

void glutPostRedisplay(void) {
  Glut& g = need_window("glutPostRedisplay");
  g.redisplay = true;
  // A display callback posts its next redisplay once; posting again is a loop inside
  // it, each turn a frame (counted here unless a glutSwapBuffers counted it).
  if (g.in_display) {
    if (g.posts_in_display++ > 0 && g.frames == g.frames_at_post) {
      end_if_past_limit(g);
      count_frame(g);
    }
    g.frames_at_post = g.frames;
  }
}

void glutSwapBuffers(void) {
  Glut& g = need_window("glutSwapBuffers");
  end_if_past_limit(g);
  show_frame(g);
}

void glutDisplayFunc(void (*callback)(void)) {
  if (!callback) fail("glutDisplayFunc: the display callback cannot be NULL");
  need_window("glutDisplayFunc").display = callback;
}
void glutReshapeFunc(void (*callback)(int, int)) { need_window("glutReshapeFunc").reshape = callback; }
void glutKeyboardFunc(void (*callback)(unsigned char, int, int)) { need_window("glutKeyboardFunc").keyboard = callback; }
void glutKeyboardUpFunc(void (*callback)(unsigned char, int, int)) {
  need_window("glutKeyboardUpFunc").keyboard_up = callback;
}
void glutSpecialFunc(void (*callback)(int, int, int)) { need_window("glutSpecialFunc").special = callback; }
void glutSpecialUpFunc(void (*callback)(int, int, int)) { need_window("glutSpecialUpFunc").special_up = callback; }
void glutMouseFunc(void (*callback)(int, int, int, int)) { need_window("glutMouseFunc").mouse = callback; }
void glutMotionFunc(void (*callback)(int, int)) { need_window("glutMotionFunc").motion = callback; }
void glutPassiveMotionFunc(void (*callback)(int, int)) { need_window("glutPassiveMotionFunc").passive_motion = callback; }
void glutIdleFunc(void (*callback)(void)) { need_init("glutIdleFunc").idle = callback; }

void glutTimerFunc(unsigned int milliseconds, void (*callback)(int), int value) {
  Glut& g = need_init("glutTimerFunc");
  if (!callback) return;
  g.timers.push_back({Clock::now() + std::chrono::milliseconds(milliseconds), g.timer_order++, callback, value});
}

void glutMainLoop(void) {
  Glut& g = need_window("glutMainLoop");
  if (!g.display) fail("glutMainLoop: no display callback for the window (glutDisplayFunc)");
  std::vector<InputEvent> events;
  g.leave = false;
  g.in_main_loop = true;
  while (!g.leave) {
    events.clear();
    g.window->poll(events);
    if (g.script) g.script->due(double(elapsed_ms(g)) / 1000.0, events);
    for (const InputEvent& e : events) {
      dispatch(g, e);
      if (g.leave) break;
    }
    if (g.reshape_pending) {
      g.reshape_pending = false;
      if (g.reshape) {
        g.reshape(g.width, g.height);
      } else {
        glViewport(0, 0, g.width, g.height);
      }
      g.redisplay = true;
    }
    fire_timers(g);
    if (g.leave) break;
    if (velocity::glut::menu_changed() && !g.redisplay) {
      // A menu opened, closed or moved its highlight: the last frame shown again, with
      // it (not a new frame of the program's).
      g.window->present(shown(g).data(), g.width, g.height);
    }
    if (g.redisplay) {
      g.redisplay = false;
      g.in_display = true, g.posts_in_display = 0;
      g.display();
      g.in_display = false;
      if (!g.double_buffered) show_frame(g);
    } else if (g.idle) {
      g.idle();
    } else {
      // Nothing to do until an event or a timer: wait a little (the presenter polls).
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }
  g.leave = false;
  g.in_main_loop = false;
}

void glutLeaveMainLoop(void) { glut().leave = true; }

int glutGet(GLenum what) {
  Glut& g = glut();
  switch (what) {
    case GLUT_ELAPSED_TIME: return g.initialised ? int(elapsed_ms(g)) : 0;
    case GLUT_WINDOW_WIDTH: return g.window ? g.width : 0;
    case GLUT_WINDOW_HEIGHT: return g.window ? g.height : 0;
    case GLUT_WINDOW_X: return 0;
    case GLUT_WINDOW_Y: return 0;
    case GLUT_WINDOW_DOUBLEBUFFER: return g.window && g.double_buffered;
    case GLUT_SCREEN_WIDTH: return g.window ? g.window->window_size().first : 0;
    case GLUT_SCREEN_HEIGHT: return g.window ? g.window->window_size().second : 0;
    case GLUT_INIT_WINDOW_WIDTH: return g.init_width;
    case GLUT_INIT_WINDOW_HEIGHT: return g.init_height;
    case GLUT_INIT_DISPLAY_MODE: return int(g.display_mode);
    case GLUT_MENU_NUM_ITEMS: return velocity::glut::menu_items();
    default:
      std::fprintf(stderr, "velocity-glut: glutGet(0x%x): not a value this GLUT knows; returns -1\n", unsigned(what));
      return -1;
  }
}

int glutGetModifiers(void) { return glut().modifiers; }

}  // extern "C"
