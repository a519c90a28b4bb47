// The built-in demo scene: what `velocity` renders with no arguments.
#pragma once

#include "velocity/scene.hpp"

namespace velocity {

// A small showroom: side by side, flat, Gouraud, Phong with a highlight, textured,
// environment-mapped and Phong + environment-mapped objects; behind them vertex colours
// and wireframe; in front a car with a textured, environment-mapped shell whose wheels
// are child objects that follow the body and spin on their own (object hierarchy); on a
// floor, lit by an ambient, a directional and a point light. Every texture is generated.
// `time` (seconds) turns the car, its wheels and the textured cube.
Scene make_demo_scene(float time = 0.0f);

}  // namespace velocity
