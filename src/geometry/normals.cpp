#include "geometry/normals.hpp"

namespace velocity::geometry {

void average_normals(const Mesh& mesh, std::vector<Vec3>& out) {
  out.assign(mesh.positions.size(), Vec3{});
  for (const Triangle& t : mesh.triangles) {
    Vec3 a = mesh.positions[t.v[0]], b = mesh.positions[t.v[1]], c = mesh.positions[t.v[2]];
    Vec3 fn = cross(b - a, c - a);
    for (uint32_t v : t.v) out[v] += fn;
  }
}

}  // namespace velocity::geometry
