// Object hierarchy, camera and scene framing.
#include "velocity/scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "velocity/error.hpp"

namespace velocity {

Mat4 Transform::matrix() const {
  return velocity::translate(translation) * rotate_y(rotation.y) * rotate_x(rotation.x) * rotate_z(rotation.z) *
         velocity::scale(scale);
}

float Camera::fov_from_focal_length(float focal_mm, float film_height_mm) {
  return 2.0f * std::atan(film_height_mm / (2.0f * focal_mm));
}

void Camera::look_at(Vec3 target) {
  Vec3 d = target - position;
  float horizontal = std::sqrt(d.x * d.x + d.z * d.z);
  if (horizontal == 0 && d.y == 0) return;  // looking at itself: keep the orientation
  yaw = std::atan2(-d.x, -d.z);
  pitch = std::atan2(d.y, horizontal);
}

Mat4 Camera::view() const {
  // The inverse of the camera's placement T * Ry * Rx * Rz: seed 000's "translation
  // followed by rotation".
  return rotate_z(-roll) * rotate_x(-pitch) * rotate_y(-yaw) * translate(-position);
}

ViewWindow ViewWindow::pinhole(float fx, float fy, float cx, float cy, int width, int height) {
  if (!(fx > 0 && fy > 0 && std::isfinite(fx) && std::isfinite(fy) && std::isfinite(cx) && std::isfinite(cy)) ||
      width < 1 || height < 1)
    throw Error("pinhole camera: expected finite fx, fy > 0 and cx, cy, and an image of at least 1x1, got fx=" +
                std::to_string(fx) + " fy=" + std::to_string(fy) + " cx=" + std::to_string(cx) +
                " cy=" + std::to_string(cy) + " image " + std::to_string(width) + "x" + std::to_string(height));
  // Image x = fx * X / -Z + cx (camera looks down -Z); the image's left edge (x = 0) is
  // at X / -Z = -cx / fx. Image y runs down while the camera's Y runs up.
  return {-cx / fx, (float(width) - cx) / fx, -(float(height) - cy) / fy, cy / fy};
}

Mat4 Camera::projection_matrix(float aspect) const {
  if (window) {
    const ViewWindow& w = *window;
    if (projection == Projection::Orthographic) return orthographic(w.left, w.right, w.bottom, w.top, near, far);
    return frustum(w.left * near, w.right * near, w.bottom * near, w.top * near, near, far);
  }
  if (projection == Projection::Orthographic) {
    float h = ortho_height / 2;
    return orthographic(-h * aspect, h * aspect, -h, h, near, far);
  }
  return perspective(fov_y, aspect, near, far);
}

ObjectId Scene::add_object(std::string name, std::shared_ptr<const Mesh> mesh, ObjectId parent) {
  if (parent != kNoParent && parent >= objects_.size())
    throw Error("add_object '" + name + "': parent " + std::to_string(parent) + " does not exist");
  if (mesh) mesh->validate();
  Object o;
  o.name = std::move(name);
  o.mesh = std::move(mesh);
  o.parent = parent;
  objects_.push_back(std::move(o));
  return ObjectId(objects_.size() - 1);
}

std::optional<ObjectId> Scene::find(std::string_view name) const {
  for (size_t i = 0; i < objects_.size(); ++i)
    if (objects_[i].name == name) return ObjectId(i);
  return std::nullopt;
}

std::vector<Mat4> Scene::world_matrices() const {
  std::vector<Mat4> world;
  world_matrices(world);
  return world;
}

void Scene::world_matrices(std::vector<Mat4>& world) const {
  world.resize(objects_.size());
  for (size_t i = 0; i < objects_.size(); ++i) {
    const Object& o = objects_[i];
    Mat4 local = o.transform.matrix() * o.base;
    world[i] = o.parent == kNoParent ? local : world[o.parent] * local;  // parents come first
  }
}

Sphere Scene::bounds() const {
  std::vector<Mat4> world = world_matrices();
  bool any = false;
  Bounds box;
  for (size_t i = 0; i < objects_.size(); ++i) {
    const Object& o = objects_[i];
    if (!o.visible || !o.mesh || o.mesh->positions.empty()) continue;
    for (Vec3 p : o.mesh->positions) {
      Vec3 w = world[i].transform_point(p);
      if (!any) box = {w, w}, any = true;
      box.min = {std::min(box.min.x, w.x), std::min(box.min.y, w.y), std::min(box.min.z, w.z)};
      box.max = {std::max(box.max.x, w.x), std::max(box.max.y, w.y), std::max(box.max.z, w.z)};
    }
  }
  if (!any) return {};
  Sphere s{box.center(), 0};
  for (size_t i = 0; i < objects_.size(); ++i) {
    const Object& o = objects_[i];
    if (!o.visible || !o.mesh) continue;
    for (Vec3 p : o.mesh->positions) s.radius = std::max(s.radius, length(world[i].transform_point(p) - s.center));
  }
  return s;
}

void Scene::frame_camera(float aspect, Vec3 from) {
  Sphere s = bounds();
  float r = s.radius > 0 ? s.radius : 1.0f;
  // Distance at which the sphere fits both the vertical and the horizontal field of view.
  float half = camera.fov_y / 2;
  float half_h = std::atan(std::tan(half) * std::min(aspect, 1.0f));
  float d = r / std::sin(std::min(half, half_h));
  Vec3 dir = length(from) > 0 ? normalize(from) : Vec3{0, 0, 1};
  camera.position = s.center + dir * d;
  camera.pitch = camera.yaw = camera.roll = 0;
  camera.look_at(s.center);
  camera.near = std::max(d - r * 1.01f, d * 1e-3f);
  camera.far = d + r * 1.01f;
  camera.ortho_height = 2 * r;
}

}  // namespace velocity
