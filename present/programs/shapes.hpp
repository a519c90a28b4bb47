// Small generated meshes the real-time programs build their worlds from.
#pragma once

#include "velocity/mesh.hpp"

namespace velocity::realtime {

// A square pyramid, base 1 across at y = -0.5, apex at y = +0.5.
Mesh make_pyramid();
// A cylinder of radius 1 along the X axis from x = -0.5 to 0.5, with caps; `segments`
// around. Tread faces and cap faces alternate two colours (face_colors) so that a
// spinning wheel shows its spin.
Mesh make_wheel(int segments, Vec3 tread_a, Vec3 tread_b, Vec3 cap_a, Vec3 cap_b);
// A cone of radius 1 at y = 0 up to its apex at y = 1, base closed.
Mesh make_cone(int segments);
// A box from make_cube(1) with each of its six faces in its own smoothing group (hard
// edges) after `shape` moved its vertices.
template <typename F>
Mesh make_shaped_box(F&& shape) {
  Mesh m = make_cube(1.0f);
  for (Vec3& p : m.positions) p = shape(p);
  m.normals.clear();
  m.smoothing_groups.resize(m.triangles.size());
  for (size_t t = 0; t < m.triangles.size(); ++t) m.smoothing_groups[t] = 1u << (t / 2);
  compute_normals(m);
  return m;
}

}  // namespace velocity::realtime
