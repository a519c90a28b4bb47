// numpy-style arrays into a Mesh, and camera poses into yaw / pitch / roll (convert.hpp).
#include "convert.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "velocity/error.hpp"

namespace velocity::python {

namespace {

std::string shape_text(const ArrayView& a) { return std::to_string(a.rows) + "x" + std::to_string(a.cols); }

// Element (row, col) as a double; the caller has checked kind and itemsize.
double element(const ArrayView& a, size_t row, size_t col) {
  const char* p = static_cast<const char*>(a.data) + ptrdiff_t(row) * a.row_stride + ptrdiff_t(col) * a.col_stride;
  switch (a.kind) {
    case 'f':
      if (a.itemsize == 4) { float v; std::memcpy(&v, p, 4); return v; }
      else { double v; std::memcpy(&v, p, 8); return v; }
    case 'i':
      switch (a.itemsize) {
        case 1: { int8_t v; std::memcpy(&v, p, 1); return v; }
        case 2: { int16_t v; std::memcpy(&v, p, 2); return v; }
        case 4: { int32_t v; std::memcpy(&v, p, 4); return v; }
        default: { int64_t v; std::memcpy(&v, p, 8); return double(v); }
      }
    default:  // 'u' (and 'b', one byte)
      switch (a.itemsize) {
        case 1: { uint8_t v; std::memcpy(&v, p, 1); return v; }
        case 2: { uint16_t v; std::memcpy(&v, p, 2); return v; }
        case 4: { uint32_t v; std::memcpy(&v, p, 4); return v; }
        default: { uint64_t v; std::memcpy(&v, p, 8); return double(v); }
      }
  }
}

bool valid_type(const ArrayView& a) {
  switch (a.kind) {
    case 'f': return a.itemsize == 4 || a.itemsize == 8;
    case 'i':
    case 'u': return a.itemsize == 1 || a.itemsize == 2 || a.itemsize == 4 || a.itemsize == 8;
    default: return false;
  }
}

// Checks an array's shape (cols among `allowed_cols`, rows as `rows` unless 0) and
// element type; `floats_only` refuses integers (positions, normals, uvs).
void check(const ArrayView& a, const char* name, size_t rows, std::initializer_list<size_t> allowed_cols,
           bool floats_only) {
  if (!a.data && a.rows * a.cols != 0) throw Error(std::string(name) + ": no data");
  bool cols_ok = false;
  for (size_t c : allowed_cols) cols_ok |= a.cols == c;
  std::string want;
  for (size_t c : allowed_cols) want += (want.empty() ? "" : " or ") + std::string("Nx") + std::to_string(c);
  if (!cols_ok) throw ShapeError(std::string(name) + ": expected an array of shape " + want + ", got " + shape_text(a));
  if (rows && a.rows != rows)
    throw ShapeError(std::string(name) + ": expected " + std::to_string(rows) + " rows (one per vertex), got " +
                std::to_string(a.rows));
  if (!valid_type(a) || (floats_only && a.kind != 'f'))
    throw DtypeError(std::string(name) + ": expected " + (floats_only ? "float32 or float64" : "float or integer") +
                " elements, got kind '" + std::string(1, a.kind) + "' of " + std::to_string(a.itemsize) + " bytes");
}

constexpr float kMaxCoordinate = 1e18f;

// An index read as a double (any integer type), printed whole; no conversion to an
// integer type, which is undefined beyond its range (uint64 values above 2^63, say).
std::string whole_number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.0f", v);
  return text;
}

bool is_f32_packed(const ArrayView& a) { return a.kind == 'f' && a.itemsize == 4 && a.packed(); }

// Copies an N x K float array into `out` (N elements of K floats each): one memcpy when
// the layout is already that, else element by element. Rejects non-finite values.
template <typename T>
void copy_floats(const ArrayView& a, const char* name, std::vector<T>& out) {
  constexpr size_t K = sizeof(T) / sizeof(float);
  static_assert(sizeof(T) == K * sizeof(float));
  out.resize(a.rows);
  float* dst = reinterpret_cast<float*>(out.data());
  if (is_f32_packed(a) && a.cols == K) {
    if (a.rows) std::memcpy(dst, a.data, a.rows * K * sizeof(float));
  } else {
    for (size_t r = 0; r < a.rows; ++r)
      for (size_t c = 0; c < K; ++c) dst[r * K + c] = float(element(a, r, c));
  }
  for (size_t i = 0; i < a.rows * K; ++i) {
    if (!std::isfinite(dst[i]))
      throw Error(std::string(name) + "[" + std::to_string(i / K) + "] is not finite (" + std::to_string(dst[i]) + ")");
    // Beyond this, squares and cross products overflow float (normals become NaN);
    // no transform or depth buffer could place such a coordinate anyway.
    if (std::fabs(dst[i]) > kMaxCoordinate)
      throw Error(std::string(name) + "[" + std::to_string(i / K) + "] = " + std::to_string(dst[i]) +
                  " is out of range (at most 1e18 in magnitude: scale the model)");
  }
}

}  // namespace

Mesh mesh_from_arrays(const MeshArrays& in, std::string name) {
  Mesh mesh;
  mesh.name = std::move(name);
  check(in.vertices, "vertices", 0, {3}, true);
  const size_t n = in.vertices.rows;
  if (n > std::numeric_limits<uint32_t>::max()) throw Error("vertices: more than 2^32 - 1 rows");
  copy_floats(in.vertices, "vertices", mesh.positions);

  // Faces: indices checked before anything uses them.
  check(in.faces, "faces", 0, {3}, false);
  if (in.faces.kind == 'f') throw DtypeError("faces: expected integer indices, got floats");
  if (in.faces.rows == 0) throw Error("faces: the mesh has no triangles");
  mesh.triangles.resize(in.faces.rows);
  const ArrayView& f = in.faces;
  if ((f.kind == 'u' || f.kind == 'i') && f.itemsize == 4 && f.packed()) {
    std::memcpy(mesh.triangles.data(), f.data, f.rows * 3 * sizeof(uint32_t));
    for (size_t i = 0; i < f.rows; ++i)
      for (int c = 0; c < 3; ++c) {
        uint32_t v = mesh.triangles[i].v[c];
        // An int32 -1 reads as 4294967295: out of range either way, but say what it was.
        if (v >= n)
          throw Error("faces[" + std::to_string(i) + "] = " +
                      std::to_string(f.kind == 'i' ? int64_t(int32_t(v)) : int64_t(v)) + ": expected 0.." +
                      std::to_string(n ? n - 1 : 0) + " (the mesh has " + std::to_string(n) + " vertices)");
      }
  } else {
    for (size_t i = 0; i < f.rows; ++i)
      for (size_t c = 0; c < 3; ++c) {
        double v = element(f, i, c);
        if (!(v >= 0 && v < double(n)))
          throw Error("faces[" + std::to_string(i) + "] = " + whole_number(v) + ": expected 0.." +
                      std::to_string(n ? n - 1 : 0) + " (the mesh has " + std::to_string(n) + " vertices)");
        mesh.triangles[i].v[c] = uint32_t(v);
      }
  }

  if (in.uvs) {
    check(*in.uvs, "uvs", n, {2}, true);
    copy_floats(*in.uvs, "uvs", mesh.uvs);
  }
  if (in.colors) {
    const ArrayView& c = *in.colors;
    check(c, "colors", n, {3, 4}, false);
    // uint8 colours are 0..255; float ones 0..1 (clamped). Alpha is dropped: the
    // renderer's vertex colours are RGB.
    double scale = c.kind == 'f' ? 1.0 : (c.kind == 'u' && c.itemsize == 1 ? 1.0 / 255.0 : 0.0);
    if (scale == 0) throw DtypeError("colors: expected float in [0, 1] or uint8 elements");
    mesh.colors.resize(n);
    for (size_t r = 0; r < n; ++r) {
      float rgb[3];
      for (size_t k = 0; k < 3; ++k) {
        double v = element(c, r, k) * scale;
        if (!std::isfinite(v)) throw Error("colors[" + std::to_string(r) + "] is not finite");
        rgb[k] = float(std::fmin(1.0, std::fmax(0.0, v)));
      }
      mesh.colors[r] = {rgb[0], rgb[1], rgb[2]};
    }
  }
  if (in.normals) {
    check(*in.normals, "normals", n, {3}, true);
    copy_floats(*in.normals, "normals", mesh.normals);
    bool zero = false;
    for (Vec3& v : mesh.normals) {
      v = normalize(v);
      zero |= v == Vec3{};
    }
    if (zero) {  // a zero normal cannot be lit: take the averaged ones for those
      std::vector<Vec3> given = std::move(mesh.normals);
      mesh.normals.clear();
      compute_normals(mesh);
      if (mesh.normals.size() == given.size())
        for (size_t i = 0; i < given.size(); ++i)
          if (!(given[i] == Vec3{})) mesh.normals[i] = given[i];
    }
  } else {
    compute_normals(mesh);
  }
  mesh.validate();
  mesh.touch();  // a copy Python cannot edit: caches trust its revision (Mesh::revision)
  return mesh;
}

void rotation_from_angles(double yaw, double pitch, double roll, double r[9]) {
  double cy = std::cos(yaw), sy = std::sin(yaw), cp = std::cos(pitch), sp = std::sin(pitch);
  double cr = std::cos(roll), sr = std::sin(roll);
  // Ry * Rx * Rz (Transform::matrix's order), written out.
  r[0] = cy * cr + sy * sp * sr, r[1] = -cy * sr + sy * sp * cr, r[2] = sy * cp;
  r[3] = cp * sr, r[4] = cp * cr, r[5] = -sp;
  r[6] = -sy * cr + cy * sp * sr, r[7] = sy * sr + cy * sp * cr, r[8] = cy * cp;
}

CameraPose camera_pose(const double m[16]) {
  for (int i = 0; i < 16; ++i)
    if (!std::isfinite(m[i])) throw Error("camera pose: entry " + std::to_string(i / 4) + "," + std::to_string(i % 4) + " is not finite");
  if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1)
    throw Error("camera pose: the last row must be 0 0 0 1");
  // R = the upper 3x3; R^T R must be the identity and det R = +1 (no scale, no mirror).
  double r[9] = {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]};
  double worst = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double d = r[i] * r[j] + r[3 + i] * r[3 + j] + r[6 + i] * r[6 + j];
      worst = std::fmax(worst, std::fabs(d - (i == j ? 1.0 : 0.0)));
    }
  double det = r[0] * (r[4] * r[8] - r[5] * r[7]) - r[1] * (r[3] * r[8] - r[5] * r[6]) + r[2] * (r[3] * r[7] - r[4] * r[6]);
  if (worst > 1e-4 || det < 0)
    throw Error("camera pose: the upper 3x3 must be a rotation (orthonormal, determinant +1; no scale or mirror), got "
                "deviation " + std::to_string(worst) + " and determinant " + std::to_string(det));
  // R = Ry(yaw) Rx(pitch) Rz(roll): column 2 is (sin yaw cos pitch, -sin pitch,
  // cos yaw cos pitch), row 1 is (cos pitch sin roll, cos pitch cos roll, -sin pitch).
  CameraPose p;
  p.position = {float(m[3]), float(m[7]), float(m[11])};
  double pitch = std::atan2(-r[5], std::hypot(r[2], r[8]));
  double yaw, roll;
  if (std::hypot(r[2], r[8]) > 1e-9) {
    yaw = std::atan2(r[2], r[8]);
    roll = std::atan2(r[3], r[4]);
  } else {
    // Looking straight up or down: only yaw +- roll is defined; take roll = 0, and then
    // column 0 is (cos yaw, 0, -sin yaw).
    roll = 0;
    yaw = std::atan2(-r[6], r[0]);
  }
  p.yaw = float(yaw), p.pitch = float(pitch), p.roll = float(roll);
  return p;
}

Mat4 to_mat4(const double m[16], const char* what) {
  Mat4 out;
  for (int i = 0; i < 16; ++i) {
    if (!std::isfinite(m[i]))
      throw Error(std::string(what) + ": entry " + std::to_string(i / 4) + "," + std::to_string(i % 4) + " is not finite");
    out.m[i / 4][i % 4] = float(m[i]);
  }
  return out;
}

}  // namespace velocity::python
