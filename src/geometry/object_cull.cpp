#include "geometry/object_cull.hpp"

#include <algorithm>

namespace velocity::geometry {

namespace {

constexpr size_t kSphereTestMaxVertices = 16384;

Sphere world_sphere(const Mesh& mesh, const Mat4& world) {
  Sphere s = mesh.bounding_sphere();
  float stretch = 0;
  for (int c = 0; c < 3; ++c) stretch = std::max(stretch, length({world.m[0][c], world.m[1][c], world.m[2][c]}));
  return {world.transform_point(s.center), s.radius * stretch};
}

}  // namespace

ViewVolume::ViewVolume(const Mat4& vp) {
  auto row = [&](int r) { return Vec4{vp.m[r][0], vp.m[r][1], vp.m[r][2], vp.m[r][3]}; };
  Vec4 r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
  Vec4 p[6] = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2, r3 - r2};
  for (int i = 0; i < 6; ++i) {
    float len = length(p[i].xyz());
    planes_[i] = len > 0 ? p[i] * (1.0f / len) : p[i];
  }
}

bool ViewVolume::outside(const Mesh& mesh, const Mat4& world) const {
  if (mesh.positions.size() > kSphereTestMaxVertices) return false;
  const Sphere s = world_sphere(mesh, world);
  for (const Vec4& p : planes_)
    if (dot(p.xyz(), s.center) + p.w < -s.radius) return true;
  return false;
}

}  // namespace velocity::geometry
