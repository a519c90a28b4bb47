#include "sdl/presenter.hpp"

#include <SDL.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <utility>

#include "velocity/error.hpp"

namespace velocity::present {

using realtime::InputEvent;
using realtime::Key;

namespace {

Key translate_key(SDL_Keycode k) {
  switch (k) {
    case SDLK_LEFT: return realtime::KeyLeft;
    case SDLK_RIGHT: return realtime::KeyRight;
    case SDLK_UP: return realtime::KeyUp;
    case SDLK_DOWN: return realtime::KeyDown;
    case SDLK_LCTRL:
    case SDLK_RCTRL: return realtime::KeyCtrl;
    case SDLK_LSHIFT:
    case SDLK_RSHIFT: return realtime::KeyShift;
    case SDLK_PAGEUP: return realtime::KeyPageUp;
    case SDLK_PAGEDOWN: return realtime::KeyPageDown;
    case SDLK_RETURN:
    case SDLK_KP_ENTER: return realtime::KeyEnter;
    case SDLK_KP_PLUS: return Key('+');
    case SDLK_KP_MINUS: return Key('-');
    default: break;
  }
  if (k >= SDLK_F1 && k <= SDLK_F12) return Key(realtime::KeyF1 + (k - SDLK_F1));
  if (k > 0 && k < 127) return Key(k);  // SDL keycodes are ASCII for these (lowercase letters)
  return realtime::KeyNone;
}

// SDL's video drivers that draw nowhere a person can see.
bool is_invisible_driver(const char* name) {
  return name && (SDL_strcasecmp(name, "offscreen") == 0 || SDL_strcasecmp(name, "dummy") == 0 ||
                  SDL_strcasecmp(name, "evdev") == 0);
}

}  // namespace

// The window's OpenGL context as the GPU backend binds it (velocity/backend.hpp).
struct SdlGlContext final : GlContextProvider {
  SDL_Window* window = nullptr;
  SDL_GLContext context = nullptr;
  bool make_current(std::string& error) override {
    if (SDL_GL_MakeCurrent(window, context) == 0) return true;
    error = SDL_GetError();
    return false;
  }
  bool is_current() const override { return SDL_GL_GetCurrentContext() == context; }
  std::string name() const override {
    const char* driver = SDL_GetCurrentVideoDriver();
    return std::string("SDL GL context (") + (driver ? driver : "?") + ")";
  }
};

struct SdlPresenter::Impl {
  SDL_Window* window = nullptr;
  SDL_Renderer* renderer = nullptr;
  SdlGlContext gl;          // gl.context is null unless the window draws through OpenGL
  std::string gl_missing;   // why it does not, when it was asked to
  bool exposed = false;     // uncovered since take_exposed()
  bool vsync = true;
  SDL_Texture* texture = nullptr;
  int tex_w = 0, tex_h = 0;
  bool fullscreen = false;
  SDL_GameController* pad = nullptr;  // the first game controller, while connected
  bool pads = false;                  // the game controller subsystem started
};

namespace {

// A controller's buttons as keys: the d-pad as arrows, A as Enter, B and Back as Esc,
// Start as P (pause).
realtime::Key controller_key(int button) {
  switch (button) {
    case SDL_CONTROLLER_BUTTON_DPAD_UP: return realtime::KeyUp;
    case SDL_CONTROLLER_BUTTON_DPAD_DOWN: return realtime::KeyDown;
    case SDL_CONTROLLER_BUTTON_DPAD_LEFT: return realtime::KeyLeft;
    case SDL_CONTROLLER_BUTTON_DPAD_RIGHT: return realtime::KeyRight;
    case SDL_CONTROLLER_BUTTON_A: return realtime::KeyEnter;
    case SDL_CONTROLLER_BUTTON_B:
    case SDL_CONTROLLER_BUTTON_BACK: return realtime::KeyEscape;
    case SDL_CONTROLLER_BUTTON_START: return realtime::Key('p');
    default: return realtime::KeyNone;
  }
}

}  // namespace

SdlPresenter::SdlPresenter(const WindowOptions& o) : impl_(std::make_unique<Impl>()) {
  const bool chosen = SDL_GetHint(SDL_HINT_VIDEODRIVER) != nullptr;  // SDL_VIDEODRIVER
  if (!chosen) {
    // Only the drivers that show a window. Wayland cannot connect without
    // XDG_RUNTIME_DIR (and its library would print an error saying so).
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    bool no_wayland = !std::getenv("XDG_RUNTIME_DIR") && !(wayland && wayland[0] == '/');
    std::string drivers;
    for (int i = 0; i < SDL_GetNumVideoDrivers(); ++i) {
      const char* name = SDL_GetVideoDriver(i);
      if (is_invisible_driver(name) || (no_wayland && SDL_strcasecmp(name, "wayland") == 0)) continue;
      drivers += (drivers.empty() ? "" : ",") + std::string(name);
    }
    if (!drivers.empty()) SDL_SetHint(SDL_HINT_VIDEODRIVER, drivers.c_str());
  }
  bool opened = SDL_InitSubSystem(SDL_INIT_VIDEO) == 0;
  if (!opened || (!chosen && is_invisible_driver(SDL_GetCurrentVideoDriver()))) {
    if (opened) SDL_QuitSubSystem(SDL_INIT_VIDEO);
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY"))
      throw Error("cannot open a window: no display (DISPLAY and WAYLAND_DISPLAY are not set)");
    throw Error(std::string("cannot open a window: ") + SDL_GetError());
  }
  // Nearest filtering: a 320x200 frame stays crisp pixels at any window size.
  SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "nearest");
  SDL_SetHint(SDL_HINT_RENDER_VSYNC, o.vsync ? "1" : "0");
  int pos = o.at_origin ? 0 : SDL_WINDOWPOS_CENTERED;
  Uint32 flags = SDL_WINDOW_RESIZABLE | (o.fullscreen ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0);
  impl_->fullscreen = o.fullscreen;
  impl_->vsync = o.vsync;
  if (o.opengl) open_gl_window(o, pos, flags);
  if (!impl_->window) impl_->window = SDL_CreateWindow(o.title.c_str(), pos, pos, o.width, o.height, flags);
  if (!impl_->window) {
    std::string why = SDL_GetError();
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    throw Error("cannot open a window: " + why);
  }
  if (!impl_->gl.context) {
    try {
      open_renderer();
    } catch (const Error&) {
      SDL_DestroyWindow(impl_->window);
      SDL_QuitSubSystem(SDL_INIT_VIDEO);
      throw;
    }
  }
  SDL_EventState(SDL_DROPFILE, SDL_ENABLE);
  // Game controllers are optional: without the subsystem there is just no gamepad.
  impl_->pads = SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) == 0;
}

// An OpenGL window with a 3.3 core context (no depth buffer: the backend draws into its
// own framebuffer object and only blits here). On failure, no window and why in
// gl_missing: the caller opens the streaming-texture one.
void SdlPresenter::open_gl_window(const WindowOptions& o, int pos, uint32_t flags) {
  Impl& m = *impl_;
  SDL_GL_ResetAttributes();
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);
  SDL_Window* window = SDL_CreateWindow(o.title.c_str(), pos, pos, o.width, o.height, flags | SDL_WINDOW_OPENGL);
  if (!window) {
    m.gl_missing = std::string("no OpenGL window: ") + SDL_GetError();
    SDL_GL_ResetAttributes();
    return;
  }
  SDL_GLContext context = SDL_GL_CreateContext(window);
  if (!context) {
    m.gl_missing = std::string("no OpenGL 3.3 core context for the window: ") + SDL_GetError();
    SDL_DestroyWindow(window);
    SDL_GL_ResetAttributes();
    return;
  }
  SDL_GL_SetSwapInterval(o.vsync ? 1 : 0);  // (a driver without the control keeps its own)
  m.window = window;
  m.gl.window = window, m.gl.context = context;
}

// The streaming-texture path: an SDL_Renderer on the window, accelerated when SDL has one.
void SdlPresenter::open_renderer() {
  Impl& m = *impl_;
  Uint32 rflags = m.vsync ? SDL_RENDERER_PRESENTVSYNC : 0;
  m.renderer = SDL_CreateRenderer(m.window, -1, SDL_RENDERER_ACCELERATED | rflags);
  if (!m.renderer) m.renderer = SDL_CreateRenderer(m.window, -1, SDL_RENDERER_SOFTWARE);
  if (!m.renderer) throw Error(std::string("cannot draw to the window: ") + SDL_GetError());
}

GlContextProvider* SdlPresenter::gl_context() { return impl_->gl.context ? &impl_->gl : nullptr; }

std::string SdlPresenter::gl_missing() const { return impl_->gl_missing; }

void SdlPresenter::drop_gl_context(const std::string& why) {
  Impl& m = *impl_;
  if (!m.gl.context) return;
  SDL_GL_MakeCurrent(m.window, nullptr);
  SDL_GL_DeleteContext(m.gl.context);
  m.gl.context = nullptr;
  m.gl_missing = why;
  SDL_GL_ResetAttributes();  // SDL's own renderer asks for the context it needs
  open_renderer();
}

void SdlPresenter::swap() {
  if (impl_->gl.context) SDL_GL_SwapWindow(impl_->window);
}

bool SdlPresenter::take_exposed() { return std::exchange(impl_->exposed, false); }

realtime::GamepadState SdlPresenter::gamepad() const {
  realtime::GamepadState g;
  SDL_GameController* pad = impl_->pad;
  if (!pad || !SDL_GameControllerGetAttached(pad)) return g;
  auto axis = [&](SDL_GameControllerAxis a) {
    return std::clamp(float(SDL_GameControllerGetAxis(pad, a)) / 32767.0f, -1.0f, 1.0f);
  };
  g.connected = true;
  g.steer = axis(SDL_CONTROLLER_AXIS_LEFTX);
  g.pitch = axis(SDL_CONTROLLER_AXIS_LEFTY);
  g.throttle = std::max(0.0f, axis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT));
  g.brake = std::max(0.0f, axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT));
  return g;
}

SdlPresenter::~SdlPresenter() {
  if (impl_->pad) SDL_GameControllerClose(impl_->pad);
  if (impl_->pads) SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
  if (impl_->texture) SDL_DestroyTexture(impl_->texture);
  if (impl_->renderer) SDL_DestroyRenderer(impl_->renderer);
  if (impl_->gl.context) {
    SDL_GL_MakeCurrent(impl_->window, nullptr);
    SDL_GL_DeleteContext(impl_->gl.context);
  }
  SDL_DestroyWindow(impl_->window);
  SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

void SdlPresenter::poll(std::vector<InputEvent>& out) {
  SDL_Event ev;
  while (SDL_PollEvent(&ev)) {
    InputEvent e;
    switch (ev.type) {
      case SDL_QUIT: e.kind = InputEvent::Quit; break;
      case SDL_KEYDOWN:
      case SDL_KEYUP:
        if (ev.key.repeat) continue;
        e.kind = ev.type == SDL_KEYDOWN ? InputEvent::KeyDown : InputEvent::KeyUp;
        e.key = translate_key(ev.key.keysym.sym);
        if (e.key == realtime::KeyNone) continue;
        // Alt+Enter toggles fullscreen, as F11 does.
        if (e.key == realtime::KeyEnter && (ev.key.keysym.mod & KMOD_ALT)) e.key = realtime::KeyF11;
        break;
      case SDL_CONTROLLERDEVICEADDED:
        if (!impl_->pad && SDL_IsGameController(ev.cdevice.which)) impl_->pad = SDL_GameControllerOpen(ev.cdevice.which);
        continue;
      case SDL_CONTROLLERDEVICEREMOVED:
        if (impl_->pad && SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(impl_->pad)) == ev.cdevice.which) {
          SDL_GameControllerClose(impl_->pad);
          impl_->pad = nullptr;
        }
        continue;
      case SDL_CONTROLLERBUTTONDOWN:
      case SDL_CONTROLLERBUTTONUP:
        e.kind = ev.type == SDL_CONTROLLERBUTTONDOWN ? InputEvent::KeyDown : InputEvent::KeyUp;
        e.key = controller_key(ev.cbutton.button);
        if (e.key == realtime::KeyNone) continue;
        break;
      case SDL_MOUSEMOTION:
        // With a logical size set, SDL gives positions in frame pixels.
        e.kind = InputEvent::MouseMove;
        e.x = ev.motion.x, e.y = ev.motion.y;
        break;
      case SDL_MOUSEBUTTONDOWN:
      case SDL_MOUSEBUTTONUP:
        e.kind = ev.type == SDL_MOUSEBUTTONDOWN ? InputEvent::MouseDown : InputEvent::MouseUp;
        e.button = ev.button.button == SDL_BUTTON_RIGHT    ? realtime::MouseButton::Right
                   : ev.button.button == SDL_BUTTON_MIDDLE ? realtime::MouseButton::Middle
                                                           : realtime::MouseButton::Left;
        e.x = ev.button.x, e.y = ev.button.y;
        break;
      case SDL_MOUSEWHEEL:
        e.kind = InputEvent::Wheel;
        e.wheel = ev.wheel.preciseY;
        break;
      case SDL_DROPFILE:
        e.kind = InputEvent::Drop;
        if (ev.drop.file) {
          e.path = ev.drop.file;
          SDL_free(ev.drop.file);
        }
        break;
      case SDL_WINDOWEVENT:
        // Uncovered: show the last frame again (an idle program draws no new one).
        if (ev.window.event == SDL_WINDOWEVENT_EXPOSED && impl_->gl.context) impl_->exposed = true;
        if (ev.window.event == SDL_WINDOWEVENT_EXPOSED && impl_->texture && impl_->renderer) {
          SDL_RenderClear(impl_->renderer);
          SDL_RenderCopy(impl_->renderer, impl_->texture, nullptr, nullptr);
          SDL_RenderPresent(impl_->renderer);
        }
        if (ev.window.event != SDL_WINDOWEVENT_SIZE_CHANGED) continue;
        e.kind = InputEvent::Resize;
        std::tie(e.x, e.y) = window_size();
        break;
      default: continue;
    }
    out.push_back(std::move(e));
  }
}

void SdlPresenter::present(const uint8_t* rgba, int width, int height) {
  Impl& m = *impl_;
  if (!m.renderer) throw Error("present: this window draws through its OpenGL context (swap)");
  if (!m.texture || m.tex_w != width || m.tex_h != height) {
    if (m.texture) SDL_DestroyTexture(m.texture);
    // RGBA bytes in memory are SDL's ABGR8888 on a little-endian machine (RGBA32 names
    // the byte order on any machine).
    m.texture = SDL_CreateTexture(m.renderer, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STREAMING, width, height);
    if (!m.texture) throw Error(std::string("cannot create the frame texture: ") + SDL_GetError());
    m.tex_w = width, m.tex_h = height;
    // Letterbox: the frame keeps its aspect ratio in any window.
    SDL_RenderSetLogicalSize(m.renderer, width, height);
  }
  void* dst = nullptr;
  int pitch = 0;
  if (SDL_LockTexture(m.texture, nullptr, &dst, &pitch) == 0) {
    for (int y = 0; y < height; ++y)
      std::copy_n(rgba + size_t(y) * width * 4, size_t(width) * 4, static_cast<uint8_t*>(dst) + size_t(y) * pitch);
    SDL_UnlockTexture(m.texture);
  }
  SDL_SetRenderDrawColor(m.renderer, 0, 0, 0, 255);
  SDL_RenderClear(m.renderer);
  SDL_RenderCopy(m.renderer, m.texture, nullptr, nullptr);
  SDL_RenderPresent(m.renderer);  // waits for vertical sync (SDL_RENDERER_PRESENTVSYNC)
}

void SdlPresenter::set_title(const std::string& title) { SDL_SetWindowTitle(impl_->window, title.c_str()); }

void SdlPresenter::toggle_fullscreen() {
  impl_->fullscreen = !impl_->fullscreen;
  SDL_SetWindowFullscreen(impl_->window, impl_->fullscreen ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0);
}

std::pair<int, int> SdlPresenter::window_size() const {
  int w = 0, h = 0;
  if (impl_->gl.context) SDL_GL_GetDrawableSize(impl_->window, &w, &h);
  else SDL_GetRendererOutputSize(impl_->renderer, &w, &h);
  return {std::max(w, 1), std::max(h, 1)};
}

std::string SdlPresenter::driver() const {
  if (impl_->gl.context)
    return std::string(SDL_GetCurrentVideoDriver() ? SDL_GetCurrentVideoDriver() : "?") + "/opengl-context";
  SDL_RendererInfo info{};
  SDL_GetRendererInfo(impl_->renderer, &info);
  return std::string(SDL_GetCurrentVideoDriver() ? SDL_GetCurrentVideoDriver() : "?") + "/" +
         (info.name ? info.name : "?");
}

bool SdlPresenter::invisible() const { return is_invisible_driver(SDL_GetCurrentVideoDriver()); }

namespace {

void audio_callback(void* user, Uint8* stream, int len) {
  // SDL starts its audio thread at TIME_CRITICAL priority, which on Linux is nice -20
  // where the process may raise it (root, CAP_SYS_NICE). With the scheduler's groups
  // (autogroup, cgroups) the process's threads share one weight, split between the
  // processors by the weight of the threads there: a nice -20 thread, even one that
  // sleeps 99 % of the time, draws the group's share to its processor and starves the
  // rasterizer's threads on the other one. On a loaded machine the frame took twice as
  // long (p99 180-230 ms against 65-80 ms muted). The synthesiser needs about 0.1 ms a
  // buffer (23 ms), so a normal priority is plenty: set once, from the audio thread.
  thread_local bool normal_priority = false;
  if (!normal_priority) {
    SDL_SetThreadPriority(SDL_THREAD_PRIORITY_NORMAL);
    normal_priority = true;
  }
  static_cast<realtime::Synth*>(user)->render(reinterpret_cast<int16_t*>(stream), size_t(len) / 2);
}

// Whether the machine could have a sound device: a sound card, a sound server, or a
// driver chosen by hand (SDL_AUDIODRIVER, e.g. disk). Without one, ALSA would print
// errors while SDL looked for a device.
bool may_have_sound() {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (std::getenv("SDL_AUDIODRIVER") || std::getenv("PULSE_SERVER") || fs::exists("/dev/snd", ec)) return true;
  const char* run = std::getenv("XDG_RUNTIME_DIR");
  return run && (fs::exists(fs::path(run) / "pulse" / "native", ec) || fs::exists(fs::path(run) / "pipewire-0", ec));
}

}  // namespace

SdlAudio::SdlAudio(realtime::Synth& synth) : synth_(synth) {
  // No audio: silently off.
  if (!may_have_sound() || SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) return;
  SDL_AudioSpec want{}, have{};
  want.freq = synth.sample_rate();
  want.format = AUDIO_S16SYS;
  want.channels = 1;
  want.samples = 1024;
  want.callback = audio_callback;
  want.userdata = &synth_;
  device_ = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0);  // exactly this format: SDL converts
  if (device_ == 0) {
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
    return;
  }
  SDL_PauseAudioDevice(device_, 0);
}

SdlAudio::~SdlAudio() {
  if (device_ == 0) return;
  SDL_CloseAudioDevice(device_);
  SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

}  // namespace velocity::present
