// Fuzz target: what the Python module does with a caller's arrays and poses, without
// Python (python/src/convert.cpp): numpy-style arrays of any type, shape and stride
// into a Mesh, a 4x4 camera pose into yaw / pitch / roll, and a frame of the result.
// The input: a header that picks each array's element type, shape and strides (made to
// fit the bytes that follow, as numpy guarantees), then the array data; the last 128
// bytes, when there are that many, are a camera pose as 16 doubles.
// Property: mesh_from_arrays returns a mesh that validates or throws velocity::Error;
// camera_pose accepts only rotations, whose angles rebuild the pose; never a read
// outside the input.
#include <cmath>
#include <cstring>

#include "convert.hpp"
#include "fuzz_util.hpp"
#include "scene_graph.hpp"
#include "velocity/error.hpp"

namespace {

using velocity::python::ArrayView;

struct Reader {
  const uint8_t* p;
  size_t n;
  uint8_t byte() { return n ? (--n, *p++) : 0; }
};

// An array view over `data` (size bytes) with the header's type and shape, shrunk until
// every element it addresses lies inside the data.
ArrayView make_view(Reader& h, const uint8_t* data, size_t size, size_t cols_default) {
  static const char kinds[] = {'f', 'f', 'i', 'u', 'i', 'u', 'b'};
  static const int sizes[] = {4, 8, 4, 4, 8, 1, 1};
  int t = h.byte() % 7;
  ArrayView v;
  v.kind = kinds[t];
  v.itemsize = sizes[t];
  v.cols = h.byte() % 5 == 0 ? h.byte() % 6 : cols_default;
  v.rows = h.byte() % 40;
  int layout = h.byte() % 4;  // packed, padded rows, column-major, reversed rows
  size_t pad = layout == 1 ? size_t(h.byte() % 3) * v.itemsize : 0;
  v.col_stride = layout == 2 ? ptrdiff_t(v.rows * v.itemsize) : v.itemsize;
  v.row_stride = layout == 2 ? v.itemsize : ptrdiff_t(v.cols * v.itemsize + pad);
  auto extent = [&] {
    if (v.rows == 0 || v.cols == 0) return size_t(0);
    return size_t((v.rows - 1) * std::abs(v.row_stride) + (v.cols - 1) * std::abs(v.col_stride) + v.itemsize);
  };
  while (v.rows && extent() > size) {
    --v.rows;
    if (layout == 2) v.col_stride = ptrdiff_t(v.rows * v.itemsize);
  }
  v.data = data;
  if (layout == 3 && v.rows) {  // negative row stride: start at the last row
    v.data = data + (v.rows - 1) * size_t(v.row_stride);
    v.row_stride = -v.row_stride;
  }
  return v;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace velocity;
  using namespace velocity::python;
  Reader header{data, std::min<size_t>(size, 24)};
  size_t skip = std::min<size_t>(size, 24);
  const uint8_t* body = data + skip;
  size_t body_size = size - skip;
  double pose[16];
  bool have_pose = body_size >= 128 + 8;
  if (have_pose) {
    std::memcpy(pose, body + body_size - 128, 128);
    body_size -= 128;
  }
  MeshArrays arrays;
  uint8_t which = header.byte();
  arrays.vertices = make_view(header, body, body_size, 3);
  arrays.faces = make_view(header, body + body_size / 2, body_size - body_size / 2, 3);
  if (which & 1) arrays.normals = make_view(header, body, body_size, 3);
  if (which & 2) arrays.uvs = make_view(header, body + body_size / 3, body_size - body_size / 3, 2);
  if (which & 4) arrays.colors = make_view(header, body, body_size, 4);
  try {
    Mesh mesh = mesh_from_arrays(arrays, "fuzz");
    mesh.validate();
    fuzz_check(mesh.positions.size() == arrays.vertices.rows);
    for (const Triangle& t : mesh.triangles)
      for (uint32_t i : t.v) fuzz_check(i < mesh.positions.size());
    for (Vec3 n : mesh.normals) fuzz_check(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
  } catch (const Error&) {
  }
  if (have_pose) {
    try {
      CameraPose p = camera_pose(pose);
      double r[9];
      rotation_from_angles(p.yaw, p.pitch, p.roll, r);
      const double given[9] = {pose[0], pose[1], pose[2], pose[4], pose[5], pose[6], pose[8], pose[9], pose[10]};
      for (int i = 0; i < 9; ++i) fuzz_check(std::fabs(r[i] - given[i]) < 1e-3);
    } catch (const Error&) {
    }
  }
  return 0;
}
