// A real-time program (the viewer, the flythrough, the driving simulation) as the main
// loop sees it: events in, fixed or measured time steps, and each frame described as
// data (a scene to render, render options, a 2D layer on top). Nothing here knows
// about SDL, so tests drive programs directly and deterministically.
#pragma once

#include <string>

#include "runtime/canvas.hpp"
#include "runtime/input.hpp"
#include "velocity/renderer.hpp"
#include "velocity/scene.hpp"

namespace velocity::realtime {

class Synth;

// One frame, as the program wants it drawn. The render thread owns it once handed over.
struct FrameDescription {
  Scene scene;
  bool draw_scene = true;   // false: just the background colour and the 2D layer
  RenderOptions options;
  DrawList overlay;         // drawn over the 3D image
  std::string screenshot;   // when set, the finished frame is also written there (PNG)
  bool screenshot_overlay = true;  // false: the screenshot is the 3D image alone
};

class Program {
 public:
  virtual ~Program() = default;
  // The frame size in pixels; called before the first update and whenever it changes.
  virtual void resize(int width, int height) {
    width_ = width;
    height_ = height;
  }
  virtual void event(const InputEvent& e, const InputState& input) = 0;
  // Advances the program by `dt` seconds.
  virtual void update(double dt, const InputState& input) = 0;
  // Describes the current state as a frame (called once after each update).
  virtual void frame(FrameDescription& out) = 0;
  // Pushes sound parameters (engine pitch, effects, music) to the synthesiser.
  virtual void sound(Synth&) {}
  virtual bool finished() const = 0;
  // Whether the next frame would differ from the last one described, with no input since.
  // A program that knows returns false when idle, and the main loop then draws nothing
  // until input comes (in a window, when no fixed step or frame count is asked for).
  virtual bool changed() const { return true; }
  virtual std::string title() const = 0;
  // The game controller's state, before each update (connected = false when there is none).
  virtual void set_gamepad(const GamepadState&) {}
  // A screen mode the program asks for (index into the loop's modes, 4 = the window's
  // size); -1 for none. The loop switches when it changes, as F2 does.
  virtual int screen_mode() const { return -1; }

  int width() const { return width_; }
  int height() const { return height_; }

 protected:
  int width_ = 640, height_ = 480;
};

}  // namespace velocity::realtime
