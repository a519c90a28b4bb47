// A small animated glTF for the tests: a box (0..0.6, 0..0.3, 0..0.2: off its origin,
// so turning shows) at node "mover", the child of "base" (translated (0, 1, 0)). Its
// animation "move" runs 2 s: translation LINEAR (0, 0, 0) at 0 s to (2, 0, 0) at 2 s,
// rotation LINEAR from none at 0 s to a quarter turn about +Y at 2 s, scale STEP 1 at
// 0 s and 2 at 0.8 s. With `animated` false: no animation, and "mover" stands where
// `t`, `r`, `s` put it (the pose the tests compare with). With `second`, a second
// animation "lift" moves "base" alone: translation LINEAR (0, 1, 0) at 0 s to (0, 3, -1)
// at 1.6 s.
#pragma once

#include <cmath>
#include <vector>

#include "gltf_test_util.hpp"

namespace velocity::test {

inline std::string animated_box_gltf(bool animated, std::vector<float> t = {0, 0, 0},
                                     std::vector<float> r = {0, 0, 0, 1}, std::vector<float> s = {1, 1, 1},
                                     bool second = false) {
  GltfBuilder b;
  std::vector<float> p;
  for (int i = 0; i < 8; ++i) p.insert(p.end(), {i & 1 ? 0.6f : 0.0f, i & 2 ? 0.3f : 0.0f, i & 4 ? 0.2f : 0.0f});
  const int pos = b.floats(p, "VEC3", 3);
  // Twelve triangles, counter-clockwise seen from outside.
  const int idx = b.indices({0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                             2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5});
  nlohmann::json primitive = {{"attributes", {{"POSITION", pos}}}, {"indices", idx}};
  nlohmann::json mesh = {{"primitives", nlohmann::json::array({primitive})}};
  b.json["meshes"] = nlohmann::json::array({mesh});
  nlohmann::json mover = {{"name", "mover"}, {"mesh", 0}, {"translation", t}, {"rotation", r}, {"scale", s}};
  b.json["nodes"] = {{{"name", "base"}, {"translation", {0, 1, 0}}, {"children", {1}}}, mover};
  b.json["scenes"] = {{{"nodes", {0}}}};
  b.json["scene"] = 0;
  if (animated) {
    const float h = std::sin(3.14159265f / 4);  // a quarter turn: sin and cos of 45 degrees
    const int times2 = b.floats({0, 2}, "SCALAR", 1), step_times = b.floats({0, 0.8f}, "SCALAR", 1);
    const int moves = b.floats({0, 0, 0, 2, 0, 0}, "VEC3", 3);
    const int turns = b.floats({0, 0, 0, 1, 0, h, 0, h}, "VEC4", 4);
    const int sizes = b.floats({1, 1, 1, 2, 2, 2}, "VEC3", 3);
    b.json["animations"] = {
        {{"name", "move"},
         {"samplers",
          {{{"input", times2}, {"output", moves}},
           {{"input", times2}, {"output", turns}, {"interpolation", "LINEAR"}},
           {{"input", step_times}, {"output", sizes}, {"interpolation", "STEP"}}}},
         {"channels",
          {{{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}},
           {{"sampler", 1}, {"target", {{"node", 1}, {"path", "rotation"}}}},
           {{"sampler", 2}, {"target", {{"node", 1}, {"path", "scale"}}}}}}}};
  }
  if (animated && second) {
    const int times = b.floats({0, 1.6f}, "SCALAR", 1), lifts = b.floats({0, 1, 0, 0, 3, -1}, "VEC3", 3);
    b.json["animations"].push_back({{"name", "lift"},
                                    {"samplers", {{{"input", times}, {"output", lifts}}}},
                                    {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}});
  }
  return b.gltf();
}

}  // namespace velocity::test
