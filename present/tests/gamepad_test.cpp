// The window's game controller (issue 21): SDL's GameController API, driven by SDL 2.26's
// virtual joystick (SDL_JoystickAttachVirtualEx) on the dummy video driver. Its sticks and
// triggers reach the games as a GamepadState, its buttons as keys.
#include <gtest/gtest.h>

#include <SDL.h>

#include <cstdlib>

#include "sdl/presenter.hpp"

using namespace velocity;

namespace {

std::vector<realtime::InputEvent> poll_a_while(present::SdlPresenter& window) {
  std::vector<realtime::InputEvent> events;
  for (int i = 0; i < 20; ++i) {
    window.poll(events);
    SDL_Delay(2);
  }
  return events;
}

}  // namespace

TEST(Gamepad, AVirtualControllerDrivesThroughTheGameControllerApi) {
  ::setenv("SDL_VIDEODRIVER", "dummy", 1);
  // The dummy window never has the focus, and SDL ignores controllers without it.
  ::setenv("SDL_JOYSTICK_ALLOW_BACKGROUND_EVENTS", "1", 1);
  present::WindowOptions o;
  o.width = 64, o.height = 48;
  present::SdlPresenter window(o);
  EXPECT_FALSE(window.gamepad().connected);  // none yet

  SDL_VirtualJoystickDesc desc;
  SDL_zero(desc);
  desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
  desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
  desc.naxes = SDL_CONTROLLER_AXIS_MAX;
  desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
  desc.name = "velocity test pad";
  // Every axis and button where SDL's GameController layout has it (SDL builds the
  // virtual controller's mapping from these masks).
  desc.button_mask = (1u << SDL_CONTROLLER_BUTTON_MAX) - 1;
  desc.axis_mask = (1u << SDL_CONTROLLER_AXIS_MAX) - 1;
  int index = SDL_JoystickAttachVirtualEx(&desc);
  ASSERT_GE(index, 0) << SDL_GetError();
  SDL_Joystick* joy = SDL_JoystickOpen(index);
  ASSERT_NE(joy, nullptr) << SDL_GetError();
  poll_a_while(window);  // the controller arrives as an event
  ASSERT_TRUE(window.gamepad().connected);

  // Left stick hard left, right trigger full, left trigger half way (a trigger's raw
  // axis runs over the whole range, -32768 released, SDL maps it to 0..32767).
  SDL_JoystickSetVirtualAxis(joy, SDL_CONTROLLER_AXIS_LEFTX, -32768);
  SDL_JoystickSetVirtualAxis(joy, SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 32767);
  SDL_JoystickSetVirtualAxis(joy, SDL_CONTROLLER_AXIS_TRIGGERLEFT, 0);
  SDL_JoystickSetVirtualButton(joy, SDL_CONTROLLER_BUTTON_A, 1);
  auto events = poll_a_while(window);
  realtime::GamepadState g = window.gamepad();
  EXPECT_FLOAT_EQ(g.steer, -1.0f);
  EXPECT_FLOAT_EQ(g.throttle, 1.0f);
  EXPECT_NEAR(g.brake, 0.5f, 0.01f);
  bool enter = false;
  for (const auto& e : events) enter |= e.kind == realtime::InputEvent::KeyDown && e.key == realtime::KeyEnter;
  EXPECT_TRUE(enter);  // A chooses, as Enter does

  SDL_JoystickSetVirtualButton(joy, SDL_CONTROLLER_BUTTON_START, 1);
  events = poll_a_while(window);
  bool pause = false;
  for (const auto& e : events) pause |= e.kind == realtime::InputEvent::KeyDown && e.key == realtime::Key('p');
  EXPECT_TRUE(pause);  // Start pauses

  SDL_JoystickClose(joy);
  SDL_JoystickDetachVirtual(index);
  poll_a_while(window);
  EXPECT_FALSE(window.gamepad().connected);
}
