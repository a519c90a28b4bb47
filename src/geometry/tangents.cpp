#include "geometry/tangents.hpp"

#include <cmath>

namespace velocity::geometry {

void generate_tangents(const Mesh& mesh, const std::vector<Vec3>& normals, const std::vector<Vec2>& uvs,
                       std::vector<Vec4>& out) {
  const size_t nv = mesh.positions.size();
  std::vector<Vec3> tan(nv), bit(nv);
  for (const Triangle& t : mesh.triangles) {
    const Vec3 p0 = mesh.positions[t.v[0]], p1 = mesh.positions[t.v[1]], p2 = mesh.positions[t.v[2]];
    const Vec2 w0 = uvs[t.v[0]], w1 = uvs[t.v[1]], w2 = uvs[t.v[2]];
    const Vec3 e1 = p1 - p0, e2 = p2 - p0;
    const float du1 = w1.x - w0.x, dv1 = w1.y - w0.y, du2 = w2.x - w0.x, dv2 = w2.y - w0.y;
    const float det = du1 * dv2 - du2 * dv1;
    if (!(std::fabs(det) > 1e-20f)) continue;
    // dP/du and dP/dv scaled by det's magnitude (area-weighted), oriented by its sign.
    const float s = det > 0 ? 1.0f : -1.0f;
    const Vec3 t_dir = (e1 * dv2 - e2 * dv1) * s, b_dir = (e2 * du1 - e1 * du2) * s;
    for (int k = 0; k < 3; ++k) tan[t.v[k]] += t_dir, bit[t.v[k]] += b_dir;
  }
  out.resize(nv);
  for (size_t i = 0; i < nv; ++i) {
    const Vec3 n = normals[i];
    Vec3 t = tan[i] - n * dot(n, tan[i]);
    if (!(dot(t, t) > 1e-30f)) {  // no uv extent: any perpendicular
      t = std::fabs(n.x) < 0.9f ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
      t = t - n * dot(n, t);
    }
    t = normalize(t);
    // glTF's bitangent, cross(N, T) * w, points up the image, where v decreases (v = 0
    // is the image's top row): an upright map has w = +1.
    const float w = dot(cross(n, t), bit[i]) > 0 ? -1.0f : 1.0f;
    out[i] = {t.x, t.y, t.z, w};
  }
}

}  // namespace velocity::geometry
