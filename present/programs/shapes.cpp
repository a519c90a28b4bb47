#include "programs/shapes.hpp"

#include <cmath>
#include <numbers>

namespace velocity::realtime {

Mesh make_pyramid() {
  Mesh m;
  m.name = "pyramid";
  m.positions = {{-0.5f, -0.5f, -0.5f}, {0.5f, -0.5f, -0.5f}, {0.5f, -0.5f, 0.5f}, {-0.5f, -0.5f, 0.5f}, {0, 0.5f, 0}};
  m.triangles = {{{0, 1, 2}}, {{0, 2, 3}}, {{3, 2, 4}}, {{2, 1, 4}}, {{1, 0, 4}}, {{0, 3, 4}}};
  compute_normals(m);
  return m;
}

Mesh make_wheel(int segments, Vec3 tread_a, Vec3 tread_b, Vec3 cap_a, Vec3 cap_b) {
  Mesh m;
  m.name = "wheel";
  const float step = 2.0f * std::numbers::pi_v<float> / float(segments);
  // Each face gets its own vertices (flat faces, hard edges).
  auto quad = [&](Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 colour) {
    uint32_t i = uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), {a, b, c, d});
    m.triangles.push_back({{i, i + 1, i + 2}});
    m.triangles.push_back({{i, i + 2, i + 3}});
    m.face_colors.insert(m.face_colors.end(), {colour, colour});
  };
  auto tri = [&](Vec3 a, Vec3 b, Vec3 c, Vec3 colour) {
    uint32_t i = uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), {a, b, c});
    m.triangles.push_back({{i, i + 1, i + 2}});
    m.face_colors.push_back(colour);
  };
  for (int s = 0; s < segments; ++s) {
    float a0 = float(s) * step, a1 = float(s + 1) * step;
    Vec3 p0{0, std::cos(a0), std::sin(a0)}, p1{0, std::cos(a1), std::sin(a1)};
    Vec3 l{-0.5f, 0, 0}, r{0.5f, 0, 0};
    quad(l + p0, l + p1, r + p1, r + p0, s % 2 ? tread_a : tread_b);
    Vec3 spoke = (s % 4 == 0) ? cap_b : cap_a;
    tri(r, r + p0, r + p1, spoke);  // right cap, facing +X
    tri(l, l + p1, l + p0, spoke);  // left cap, facing -X
  }
  // Wind every face outwards, whatever the loops above did.
  for (auto& t : m.triangles) {
    Vec3 a = m.positions[t.v[0]], b = m.positions[t.v[1]], c = m.positions[t.v[2]];
    Vec3 n = cross(b - a, c - a), centre = (a + b + c) * (1.0f / 3.0f);
    Vec3 out = std::abs(centre.x) > 0.49f && std::abs(n.x) > 1e-6f ? Vec3{centre.x, 0, 0} : Vec3{0, centre.y, centre.z};
    if (dot(n, out) < 0) std::swap(t.v[1], t.v[2]);
  }
  compute_normals(m);
  return m;
}

Mesh make_cone(int segments) {
  Mesh m;
  m.name = "cone";
  const float step = 2.0f * std::numbers::pi_v<float> / float(segments);
  for (int s = 0; s < segments; ++s) {
    float a0 = float(s) * step, a1 = float(s + 1) * step;
    Vec3 p0{std::cos(a0), 0, -std::sin(a0)}, p1{std::cos(a1), 0, -std::sin(a1)};
    uint32_t i = uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), {p0, p1, {0, 1, 0}, p1, p0, {0, 0, 0}});
    m.triangles.push_back({{i, i + 1, i + 2}});      // side
    m.triangles.push_back({{i + 3, i + 4, i + 5}});  // base, facing down
  }
  for (auto& t : m.triangles) {
    Vec3 a = m.positions[t.v[0]], b = m.positions[t.v[1]], c = m.positions[t.v[2]];
    Vec3 n = cross(b - a, c - a), centre = (a + b + c) * (1.0f / 3.0f);
    bool base = a.y == 0 && b.y == 0 && c.y == 0;
    Vec3 out = base ? Vec3{0, -1, 0} : Vec3{centre.x, 0, centre.z};
    if (dot(n, out) < 0) std::swap(t.v[1], t.v[2]);
  }
  compute_normals(m);
  return m;
}

}  // namespace velocity::realtime
