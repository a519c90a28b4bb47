// The Python module's conversions that need no Python: numpy-style arrays (pointer,
// element type, shape, strides) into a velocity::Mesh, and a 4x4 camera pose into the
// core Camera's position and yaw / pitch / roll. Kept apart from the bindings so that
// the C++ tests and a libFuzzer target (tests/fuzz/fuzz_pyconvert.cpp) drive them
// without an interpreter.
//
// Everything here treats its input as untrusted (it comes from a Python caller): bad
// shapes, types, indices and non-finite numbers throw velocity::Error with a message
// that names the argument; nothing reads outside the described memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "velocity/error.hpp"
#include "velocity/mesh.hpp"
#include "velocity/scene.hpp"

namespace velocity::python {

// A numpy argument of the wrong shape, or of the wrong element type: Python gets
// velocity.ShapeError (a ValueError) and velocity.DtypeError (a TypeError), both also
// velocity.Error.
struct ShapeError : Error {
  using Error::Error;
};
struct DtypeError : Error {
  using Error::Error;
};


// A two-dimensional array as numpy describes it (a 1-D array is rows x 1).
struct ArrayView {
  const void* data = nullptr;
  char kind = 'f';         // 'f' float, 'i' signed integer, 'u' unsigned integer, 'b' bool
  int itemsize = 4;        // bytes per element: 1, 2, 4 or 8
  size_t rows = 0, cols = 0;
  ptrdiff_t row_stride = 0, col_stride = 0;  // in bytes, may be negative

  // True when the rows are packed `cols` elements of `itemsize` bytes apart with no gap:
  // the layout of std::vector<Vec3> for float32 x 3, say.
  bool packed() const {
    return col_stride == itemsize && row_stride == ptrdiff_t(cols) * itemsize;
  }
};

struct MeshArrays {
  ArrayView vertices;                 // N x 3 float
  ArrayView faces;                    // M x 3 integer
  std::optional<ArrayView> normals;   // N x 3 float
  std::optional<ArrayView> uvs;       // N x 2 float
  std::optional<ArrayView> colors;    // N x 3 or N x 4 float in [0, 1], or uint8 (alpha dropped)
};

// Builds a mesh from the arrays: float32 packed arrays are copied with one memcpy,
// anything else element by element with a conversion. Normals are normalised (zero
// ones become the averaged normals) or, when absent, computed as smooth normals.
// Throws velocity::Error naming the argument for a wrong shape, type, a non-finite
// value or a face index outside 0..N-1.
Mesh mesh_from_arrays(const MeshArrays& arrays, std::string name);

// A camera-to-world pose (row-major 4x4, OpenGL convention: the camera looks down its
// own -Z with +Y up) as the core Camera's position and yaw, pitch, roll (Camera::view()
// inverts exactly this). Throws velocity::Error unless the pose is finite, its last row
// is 0 0 0 1 and its upper 3x3 is a rotation (orthonormal within 1e-4, determinant +1).
struct CameraPose {
  Vec3 position;
  float yaw = 0, pitch = 0, roll = 0;
};
CameraPose camera_pose(const double pose[16]);

// The same rotation as Camera::view() builds from yaw, pitch and roll, in double: the
// camera-to-world rotation Ry(yaw) Rx(pitch) Rz(roll), row-major 3x3.
void rotation_from_angles(double yaw, double pitch, double roll, double out[9]);

// A row-major 4x4 of doubles as a Mat4. Throws velocity::Error naming `what` when an
// entry is not finite.
Mat4 to_mat4(const double m[16], const char* what);

}  // namespace velocity::python
