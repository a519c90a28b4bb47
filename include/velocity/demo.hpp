// The built-in demo scene: what `velocity` renders with no arguments.
#pragma once

#include "velocity/scene.hpp"

namespace velocity {

// A small showroom: one object per shading mode side by side (flat, Gouraud, Phong with
// a highlight, vertex colours, wireframe), and a car whose wheels are child objects that
// follow the body and spin on their own (object hierarchy), on a floor grid, lit by an
// ambient, a directional and a point light. `time` (seconds) turns the car and wheels.
Scene make_demo_scene(float time = 0.0f);

}  // namespace velocity
