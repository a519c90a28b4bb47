// Whole-object rejection: a mesh whose bounding sphere lies entirely outside one plane
// of the view volume is dropped at Renderer::draw, one test instead of a pass over
// every vertex.
#pragma once

#include "velocity/math.hpp"
#include "velocity/mesh.hpp"

namespace velocity::geometry {

// The six planes of the view volume in world space (Gribb and Hartmann: rows of the
// view-projection matrix), normalised so that a sphere tests with one dot product.
class ViewVolume {
 public:
  explicit ViewVolume(const Mat4& view_projection);
  // Whether `mesh`, placed by `world`, is surely outside. Meshes over 16,384 vertices are
  // never tested (false): their bounding sphere would cost a pass over every vertex each
  // frame, and the vertex stage's region codes reject their triangles anyway.
  bool outside(const Mesh& mesh, const Mat4& world) const;

 private:
  Vec4 planes_[6];
};

}  // namespace velocity::geometry
