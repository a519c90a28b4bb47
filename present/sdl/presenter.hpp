// The SDL2 window: frames go to a streaming texture, scaled to the window with nearest
// filtering and letterboxed to keep their aspect ratio, presented with vertical sync
// (no tearing). Or, for the GPU backend (WindowOptions::opengl), the window has an
// OpenGL 3.3 core context that the backend draws in, shown by swap(). Translates SDL's
// events to realtime::InputEvent, with mouse positions in frame pixels.
#pragma once

#include <memory>
#include <string>

#include "runtime/loop.hpp"
#include "runtime/synth.hpp"

namespace velocity::present {

struct WindowOptions {
  std::string title = "Velocity";
  int width = 800, height = 600;  // the window's first size
  bool fullscreen = false;
  bool vsync = true;
  bool at_origin = false;  // place the window at (0, 0) (tests read the screen there)
  // Make the window with SDL_WINDOW_OPENGL and an OpenGL 3.3 core context for the GPU
  // backend; when SDL cannot, the streaming-texture window, with why in gl_missing().
  bool opengl = false;
};

class SdlPresenter : public realtime::Presenter {
 public:
  // Throws velocity::Error with SDL's reason when no window can be opened (no display).
  // SDL 2.26 falls back to its off-screen driver when there is no display, which would
  // run invisibly: without SDL_VIDEODRIVER naming a driver, only a driver that shows
  // a window (x11, wayland, KMSDRM, ...) is taken, and otherwise this throws saying so.
  explicit SdlPresenter(const WindowOptions& options);
  ~SdlPresenter() override;
  SdlPresenter(const SdlPresenter&) = delete;
  SdlPresenter& operator=(const SdlPresenter&) = delete;

  void poll(std::vector<realtime::InputEvent>& out) override;
  void present(const uint8_t* rgba, int width, int height) override;
  void set_title(const std::string& title) override;
  void toggle_fullscreen() override;
  std::pair<int, int> window_size() const override;
  // The first game controller SDL knows (GameController API); its buttons come through
  // poll() as keys (see runtime/input.hpp).
  realtime::GamepadState gamepad() const override;
  GlContextProvider* gl_context() override;
  std::string gl_missing() const override;
  void drop_gl_context(const std::string& why) override;
  void swap() override;
  bool take_exposed() override;
  // The video driver in use ("x11", "wayland", "dummy", ...) and the renderer's name.
  std::string driver() const;
  // Whether the window shows nowhere (SDL's dummy or offscreen driver, chosen with
  // SDL_VIDEODRIVER).
  bool invisible() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  void open_gl_window(const WindowOptions& o, int pos, uint32_t flags);
  void open_renderer();
};

// Plays a Synth through the default audio device. Opening fails silently (no device,
// no driver): `active()` says whether sound is playing.
class SdlAudio {
 public:
  explicit SdlAudio(realtime::Synth& synth);
  ~SdlAudio();
  SdlAudio(const SdlAudio&) = delete;
  SdlAudio& operator=(const SdlAudio&) = delete;
  bool active() const { return device_ != 0; }

 private:
  realtime::Synth& synth_;
  uint32_t device_ = 0;
};

}  // namespace velocity::present
