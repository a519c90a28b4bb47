// Mesh validation, bounds, normals.
#include "velocity/mesh.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <unordered_map>

#include "velocity/error.hpp"

namespace velocity {

namespace {

void check_length(const Mesh& mesh, const char* what, size_t have, size_t want) {
  if (have != 0 && have != want)
    throw Error("mesh '" + mesh.name + "': " + what + " has " + std::to_string(have) + " entries, expected 0 or " +
                std::to_string(want));
}

// Exact-position key, so vertices a file duplicated (for a uv seam, say) weld together.
struct PositionKey {
  uint32_t bits[3];
  bool operator==(const PositionKey& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
};
struct PositionHash {
  size_t operator()(const PositionKey& k) const {
    return (size_t(k.bits[0]) * 73856093u) ^ (size_t(k.bits[1]) * 19349663u) ^ (size_t(k.bits[2]) * 83492791u);
  }
};
PositionKey key_of(Vec3 p) {
  // +0.0f folds -0.0 onto 0.0: 3D Studio files write both.
  p.x += 0.0f, p.y += 0.0f, p.z += 0.0f;
  PositionKey k;
  std::memcpy(&k.bits[0], &p.x, 4);
  std::memcpy(&k.bits[1], &p.y, 4);
  std::memcpy(&k.bits[2], &p.z, 4);
  return k;
}

// Unnormalised face normal: its length is twice the area, which weights the average.
Vec3 area_normal(const Mesh& m, const Triangle& t) {
  Vec3 a = m.positions[t.v[0]], b = m.positions[t.v[1]], c = m.positions[t.v[2]];
  return cross(b - a, c - a);
}

}  // namespace

// A process-wide count: a revision names one state of one mesh's data, never reused.
void Mesh::touch() {
  static std::atomic<uint64_t> next{1};
  revision = next.fetch_add(1, std::memory_order_relaxed);
}

void Mesh::validate() const {
  size_t nv = positions.size(), nt = triangles.size();
  check_length(*this, "normals", normals.size(), nv);
  check_length(*this, "uvs", uvs.size(), nv);
  check_length(*this, "uvs1", uvs1.size(), nv);
  check_length(*this, "tangents", tangents.size(), nv);
  check_length(*this, "colors", colors.size(), nv);
  check_length(*this, "alphas", alphas.size(), nv);
  check_length(*this, "face_colors", face_colors.size(), nt);
  check_length(*this, "face_materials", face_materials.size(), nt);
  check_length(*this, "smoothing_groups", smoothing_groups.size(), nt);
  for (size_t i = 0; i < nt; ++i)
    for (uint32_t v : triangles[i].v)
      if (v >= nv)
        throw Error("mesh '" + name + "': triangle " + std::to_string(i) + " uses vertex " + std::to_string(v) +
                    ", but there are only " + std::to_string(nv));
  for (size_t i = 0; i < face_materials.size(); ++i)
    if (face_materials[i] >= materials.size())
      throw Error("mesh '" + name + "': triangle " + std::to_string(i) + " uses material " +
                  std::to_string(face_materials[i]) + ", but there are only " + std::to_string(materials.size()));
}

Bounds Mesh::bounds() const {
  if (positions.empty()) return {};
  Bounds b{positions[0], positions[0]};
  for (Vec3 p : positions) {
    b.min = {std::min(b.min.x, p.x), std::min(b.min.y, p.y), std::min(b.min.z, p.z)};
    b.max = {std::max(b.max.x, p.x), std::max(b.max.y, p.y), std::max(b.max.z, p.z)};
  }
  return b;
}

Sphere Mesh::bounding_sphere() const {
  Sphere s{bounds().center(), 0};
  for (Vec3 p : positions) s.radius = std::max(s.radius, length(p - s.center));
  return s;
}

Vec3 face_normal(const Mesh& mesh, const Triangle& t) { return normalize(area_normal(mesh, t)); }

void compute_normals(Mesh& mesh) {
  size_t nv = mesh.positions.size();
  // Weld: every vertex gets the id of the first vertex at the same position.
  std::vector<uint32_t> weld(nv);
  {
    std::unordered_map<PositionKey, uint32_t, PositionHash> first;
    first.reserve(nv);
    for (uint32_t v = 0; v < nv; ++v) weld[v] = first.try_emplace(key_of(mesh.positions[v]), v).first->second;
  }

  if (mesh.smoothing_groups.empty()) {
    std::vector<Vec3> sum(nv);
    for (const Triangle& t : mesh.triangles) {
      Vec3 n = area_normal(mesh, t);
      for (uint32_t v : t.v) sum[weld[v]] += n;
    }
    mesh.normals.resize(nv);
    for (uint32_t v = 0; v < nv; ++v) mesh.normals[v] = normalize(sum[weld[v]]);
    return;
  }

  // With smoothing groups each face corner gets the sum over the faces at its position
  // that share a group bit with its own face (group 0 smooths with nothing). A vertex
  // whose corners disagree is split, one copy per distinct normal.
  std::vector<std::vector<uint32_t>> faces_at(nv);
  for (uint32_t f = 0; f < mesh.triangles.size(); ++f)
    for (uint32_t v : mesh.triangles[f].v) faces_at[weld[v]].push_back(f);

  std::vector<Vec3> face_n(mesh.triangles.size());
  for (size_t f = 0; f < face_n.size(); ++f) face_n[f] = area_normal(mesh, mesh.triangles[f]);

  std::vector<Vec3> normals(nv);
  std::vector<bool> assigned(nv, false);
  std::vector<uint32_t> next_copy(nv, UINT32_MAX);  // chain of copies made of a vertex
  auto copy_vertex = [&](uint32_t v) {
    mesh.positions.push_back(mesh.positions[v]);
    if (!mesh.uvs.empty()) mesh.uvs.push_back(mesh.uvs[v]);
    if (!mesh.colors.empty()) mesh.colors.push_back(mesh.colors[v]);
    normals.push_back({});
    assigned.push_back(true);
    next_copy.push_back(UINT32_MAX);
    return uint32_t(mesh.positions.size() - 1);
  };
  for (uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    uint32_t groups = mesh.smoothing_groups[f];
    for (uint32_t& v : mesh.triangles[f].v) {
      // Summed in faces_at order whatever f is, so faces with the same groups get
      // bit-identical normals and share vertices.
      Vec3 sum = face_n[f];
      if (groups != 0) {
        sum = {};
        for (uint32_t g : faces_at[weld[v]])
          if (g == f || (mesh.smoothing_groups[g] & groups)) sum += face_n[g];
      }
      Vec3 n = normalize(sum);
      uint32_t w = v;
      for (;;) {
        if (!assigned[w]) { normals[w] = n, assigned[w] = true; break; }
        if (normals[w] == n) break;
        if (next_copy[w] == UINT32_MAX) {
          uint32_t c = copy_vertex(v);
          next_copy[w] = c;
          normals[c] = n;
          w = c;
          break;
        }
        w = next_copy[w];
      }
      v = w;
    }
  }
  mesh.normals = std::move(normals);
  if (mesh.revision) mesh.touch();
}

void normalize_to_unit_sphere(Mesh& mesh) {
  Sphere s = mesh.bounding_sphere();
  float k = s.radius > 0 ? 1.0f / s.radius : 1.0f;
  for (Vec3& p : mesh.positions) p = (p - s.center) * k;
  if (mesh.revision) mesh.touch();
}

Mesh make_cube(float size) {
  Mesh m;
  m.name = "cube";
  float h = size / 2;
  // Each face: outward normal n, and two in-plane axes u, v with u x v = n.
  const Vec3 faces[6][3] = {{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                            {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                            {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}}};
  for (const auto& f : faces) {
    uint32_t base = uint32_t(m.positions.size());
    const float corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& c : corner) {
      m.positions.push_back((f[0] + f[1] * c[0] + f[2] * c[1]) * h);
      m.normals.push_back(f[0]);
      m.uvs.push_back({(c[0] + 1) / 2, (1 - c[1]) / 2});  // the image upright on each face
    }
    m.triangles.push_back({{base, base + 1, base + 2}});
    m.triangles.push_back({{base, base + 2, base + 3}});
  }
  return m;
}

Mesh make_sphere(int segments) {
  if (segments < 3) throw Error("sphere: need at least 3 segments, got " + std::to_string(segments));
  if (segments > 8192) throw Error("sphere: at most 8192 segments, got " + std::to_string(segments));
  Mesh m;
  m.name = "sphere:" + std::to_string(segments);
  int rings = segments / 2;
  const float pi = std::numbers::pi_v<float>;
  for (int r = 0; r <= rings; ++r) {
    float v = float(r) / float(rings), theta = v * pi;
    for (int s = 0; s <= segments; ++s) {
      float u = float(s) / float(segments), phi = u * 2.0f * pi;
      Vec3 p{std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)};
      m.positions.push_back(p);
      m.normals.push_back(p);
      m.uvs.push_back({u, v});  // v = 0, the image's top row, at the north pole
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      uint32_t a = uint32_t(r * (segments + 1) + s), b = a + uint32_t(segments) + 1;
      m.triangles.push_back({{a, b, a + 1}});
      m.triangles.push_back({{a + 1, b, b + 1}});
    }
  return m;
}

Mesh make_torus(float major, float minor, int segments, int sides) {
  if (segments < 3 || sides < 3) throw Error("torus: need at least 3 segments and 3 sides");
  Mesh m;
  m.name = "torus";
  const float tau = 2 * std::numbers::pi_v<float>;
  for (int i = 0; i <= segments; ++i) {
    float u = float(i) / float(segments), a = u * tau;
    Vec3 dir{std::cos(a), 0, -std::sin(a)};
    for (int j = 0; j <= sides; ++j) {
      float v = float(j) / float(sides), b = v * tau;
      Vec3 n = dir * std::cos(b) + Vec3{0, std::sin(b), 0};
      m.positions.push_back(dir * major + n * minor);
      m.normals.push_back(n);
      m.uvs.push_back({u, v});
    }
  }
  for (int i = 0; i < segments; ++i)
    for (int j = 0; j < sides; ++j) {
      uint32_t a = uint32_t(i * (sides + 1) + j), b = a + uint32_t(sides) + 1;
      m.triangles.push_back({{a, b, b + 1}});
      m.triangles.push_back({{a, b + 1, a + 1}});
    }
  return m;
}

Mesh make_plane_grid(float size, int cells) {
  if (cells < 1) throw Error("plane grid: need at least 1 cell");
  Mesh m;
  m.name = "plane";
  for (int z = 0; z <= cells; ++z)
    for (int x = 0; x <= cells; ++x) {
      float u = float(x) / float(cells), v = float(z) / float(cells);
      m.positions.push_back({(u - 0.5f) * size, 0, (v - 0.5f) * size});
      m.normals.push_back({0, 1, 0});
      m.uvs.push_back({u, v});  // the image's top row at -Z: upright seen from above
    }
  for (int z = 0; z < cells; ++z)
    for (int x = 0; x < cells; ++x) {
      uint32_t a = uint32_t(z * (cells + 1) + x), b = a + uint32_t(cells) + 1;
      m.triangles.push_back({{a, b, b + 1}});
      m.triangles.push_back({{a, b + 1, a + 1}});
    }
  return m;
}

}  // namespace velocity
