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

namespace {

Vec3 encode(Vec3 n) { return n * 0.5f + Vec3{0.5f, 0.5f, 0.5f}; }

}  // namespace

void normals_as_colors(const Mesh& src, const Mat4& model_view, bool flat, Mesh& m) {
  m = Mesh{};
  m.name = src.name;
  m.positions = src.positions;
  // Unlit shading never reads them, but a mesh without normals makes the renderer
  // average some for every draw: carrying them costs less.
  m.normals = src.normals;
  m.triangles = src.triangles;
  m.face_materials = src.face_materials;
  m.materials = src.materials;
  for (Material& mat : m.materials) mat.texture.reset(), mat.env_map.reset();
  const Mat4 nm = normal_matrix(model_view);
  bool faces = flat;
  for (const Material& mat : src.materials) faces |= mat.shading == Shading::Flat;
  if (faces || src.normals.empty()) {
    m.face_colors.resize(src.triangles.size());
    for (size_t f = 0; f < src.triangles.size(); ++f)
      m.face_colors[f] = encode(normalize(nm.transform_vector(face_normal(src, src.triangles[f]))));
  } else {
    m.colors.resize(src.normals.size());
    for (size_t v = 0; v < src.normals.size(); ++v) m.colors[v] = encode(normalize(nm.transform_vector(src.normals[v])));
  }
}

Vec3 normal_from_color(const uint8_t rgba[4]) {
  return normalize({rgba[0] / 127.5f - 1, rgba[1] / 127.5f - 1, rgba[2] / 127.5f - 1});
}

}  // namespace velocity::geometry
