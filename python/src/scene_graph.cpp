// The Python module's scene, its frames and the render itself (scene_graph.hpp).
#include "scene_graph.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

#include "convert.hpp"
#include "velocity/error.hpp"

namespace velocity::python {

namespace {

void multiply(const double a[16], const double b[16], double out[16]) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      out[i * 4 + j] = a[i * 4] * b[j] + a[i * 4 + 1] * b[4 + j] + a[i * 4 + 2] * b[8 + j] + a[i * 4 + 3] * b[12 + j];
}

bool finite_positive(double v) { return std::isfinite(v) && v > 0; }

void check_clip(const CameraBase& c) {
  if (!finite_positive(c.znear)) throw Error("camera znear must be finite and > 0, got " + std::to_string(c.znear));
  if (c.zfar && !(std::isfinite(*c.zfar) && *c.zfar > c.znear))
    throw Error("camera zfar must be finite and > znear (" + std::to_string(c.znear) + "), got " +
                std::to_string(*c.zfar));
}

// The depth buffer holds window depth as float in [0, 1]: a perspective projection
// resolves the view distance z to about 6e-8 * z / znear of itself, 6 % at the far
// plane when zfar / znear = 1e6 (pyrender's default znear 0.05 with a model 8 km deep
// is 1 %). Beyond that depth is wrong, then the image empty (1e7 and more).
constexpr double kMaxFarOverNear = 1e6;

void check_depth_precision(double znear, double zfar, const char* far_is) {
  if (zfar / znear <= kMaxFarOverNear) return;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "camera znear %g is too small for %s %g: the float depth buffer resolves depth only while "
                "zfar / znear <= %g; the smallest znear that works is %g",
                znear, far_is, zfar, kMaxFarOverNear, zfar / kMaxFarOverNear);
  throw Error(buf);
}

Sphere world_sphere(const Sphere& s, const Mat4& m) {
  float stretch = 0;
  for (int c = 0; c < 3; ++c) stretch = std::max(stretch, length({m.m[0][c], m.m[1][c], m.m[2][c]}));
  return {m.transform_point(s.center), s.radius * stretch};
}

Vec3 scaled_color(const LightBase& l) {
  float k = float(l.intensity / std::numbers::pi);
  return l.color * k;
}

}  // namespace

std::shared_ptr<const MeshData> make_mesh_data(std::string name, std::vector<std::shared_ptr<const Mesh>> parts,
                                               std::vector<Mat4> poses) {
  auto d = std::make_shared<MeshData>();
  d->name = std::move(name);
  d->parts = std::move(parts);
  d->poses = std::move(poses);
  // A box around every part's bounding sphere, then a sphere around the box's centre.
  bool any = false;
  Bounds box;
  std::vector<Sphere> spheres;
  for (size_t i = 0; i < d->parts.size(); ++i) {
    if (d->parts[i]->positions.empty()) continue;
    Sphere s = world_sphere(d->parts[i]->bounding_sphere(), d->poses[i]);
    spheres.push_back(s);
    Vec3 lo = s.center - Vec3{s.radius, s.radius, s.radius}, hi = s.center + Vec3{s.radius, s.radius, s.radius};
    if (!any) box = {lo, hi}, any = true;
    box.min = {std::min(box.min.x, lo.x), std::min(box.min.y, lo.y), std::min(box.min.z, lo.z)};
    box.max = {std::max(box.max.x, hi.x), std::max(box.max.y, hi.y), std::max(box.max.z, hi.z)};
  }
  if (any) {
    d->bounds.center = box.center();
    for (const Sphere& s : spheres) d->bounds.radius = std::max(d->bounds.radius, length(s.center - d->bounds.center) + s.radius);
  }
  return d;
}

void CameraBase::validate() const { check_clip(*this); }

void PerspectiveCamera::validate() const {
  check_clip(*this);
  if (zfar) check_depth_precision(znear, *zfar, "zfar");
  if (!(std::isfinite(yfov) && yfov > 0 && yfov < std::numbers::pi))
    throw Error("PerspectiveCamera: yfov must be in (0, pi) radians, got " + std::to_string(yfov));
  if (aspect_ratio && !finite_positive(*aspect_ratio))
    throw Error("PerspectiveCamera: aspectRatio must be finite and > 0, got " + std::to_string(*aspect_ratio));
}
void PerspectiveCamera::apply(Camera& c, int, int) const {
  c.projection = Projection::Perspective;
  c.fov_y = float(yfov);
  if (aspect_ratio) {
    float t = float(std::tan(yfov / 2)), a = float(*aspect_ratio);
    c.window = ViewWindow{-t * a, t * a, -t, t};
  }
}

void OrthographicCamera::validate() const {
  check_clip(*this);
  if (!finite_positive(xmag) || !finite_positive(ymag))
    throw Error("OrthographicCamera: xmag and ymag must be finite and > 0, got " + std::to_string(xmag) + ", " +
                std::to_string(ymag));
}
void OrthographicCamera::apply(Camera& c, int, int) const {
  c.projection = Projection::Orthographic;
  c.window = ViewWindow{float(-xmag), float(xmag), float(-ymag), float(ymag)};
}

void IntrinsicsCamera::validate() const {
  check_clip(*this);
  if (zfar) check_depth_precision(znear, *zfar, "zfar");
  ViewWindow::pinhole(float(fx), float(fy), float(cx), float(cy), 1, 1);  // throws for bad values
}
void IntrinsicsCamera::apply(Camera& c, int width, int height) const {
  c.projection = Projection::Perspective;
  c.window = ViewWindow::pinhole(float(fx), float(fy), float(cx), float(cy), width, height);
}

Light DirectionalLight::make(const double w[16]) const {
  // Shines along -Z of its pose: the direction towards the light is the pose's +Z.
  return Light::directional({float(w[2]), float(w[6]), float(w[10])}, scaled_color(*this));
}

Light PointLight::make(const double w[16]) const {
  Light l = Light::point({float(w[3]), float(w[7]), float(w[11])}, scaled_color(*this));
  l.constant = 0, l.linear = 0, l.quadratic = 1;  // 1 / d^2, as pyrender's
  l.falloff = Falloff::InverseSquare;
  l.range = range ? float(*range) : 0.0f;
  return l;
}

void SpotLight::validate() const {
  if (!(std::isfinite(inner_cone) && std::isfinite(outer_cone) && inner_cone >= 0 && inner_cone < outer_cone &&
        outer_cone <= std::numbers::pi / 2))
    throw Error("SpotLight: expected 0 <= innerConeAngle < outerConeAngle <= pi/2, got " + std::to_string(inner_cone) +
                ", " + std::to_string(outer_cone));
}

Light SpotLight::make(const double w[16]) const {
  validate();
  Light l = PointLight::make(w);
  // Shines along -Z of its pose: the direction towards the light is the pose's +Z.
  Light s = Light::spot(l.position, {float(w[2]), float(w[6]), float(w[10])}, l.color, float(inner_cone),
                        float(outer_cone));
  s.constant = l.constant, s.linear = l.linear, s.quadratic = l.quadratic;
  s.falloff = l.falloff, s.range = l.range;
  return s;
}

std::vector<std::array<double, 16>> SceneData::world_poses() const {
  std::vector<std::array<double, 16>> world(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) {
    const NodeData& n = nodes[i];
    if (n.parent < 0) std::copy(n.pose, n.pose + 16, world[i].begin());
    else multiply(world[size_t(n.parent)].data(), n.pose, world[i].data());
  }
  return world;
}

SceneCopy copy_scene(const SceneData& scene, int width, int height) {
  if (scene.main_camera < 0 || scene.nodes[size_t(scene.main_camera)].removed)
    throw Error("the scene has no camera: add one with scene.add(camera, pose=...)");
  std::vector<std::array<double, 16>> world = scene.world_poses();
  SceneCopy f;
  for (size_t i = 0; i < scene.nodes.size(); ++i) {
    const NodeData& n = scene.nodes[i];
    if (n.removed) continue;
    if (n.mesh) {
      Mat4 w = to_mat4(world[i].data(), "mesh pose");
      for (size_t p = 0; p < n.mesh->parts.size(); ++p)
        f.items.push_back({n.mesh->parts[p], w * n.mesh->poses[p], uint32_t(i + 1)});
    }
    if (n.light) {
      f.lights.push_back(n.light->make(world[i].data()));
      f.lights.back().cast_shadows = n.light->cast_shadows;
    }
  }
  // Always an ambient term, so the core's default light never replaces the scene's
  // (pyrender's scenes are dark without lights, and so are these).
  f.lights.push_back(Light::ambient(scene.ambient));

  const NodeData& cn = scene.nodes[size_t(scene.main_camera)];
  const CameraBase& cam = *cn.camera;
  cam.validate();
  CameraPose pose = camera_pose(world[size_t(scene.main_camera)].data());
  f.camera.position = pose.position;
  f.camera.yaw = pose.yaw, f.camera.pitch = pose.pitch, f.camera.roll = pose.roll;
  f.camera.near = float(cam.znear);
  if (cam.zfar) {
    f.camera.far = float(*cam.zfar);
  } else {
    // No far plane given (pyrender's infinite one): just beyond the farthest mesh, which
    // keeps depth precise. Along the view axis, so it holds for any direction.
    Mat4 view = f.camera.view();
    float far = 0;
    for (const SceneCopy::Item& item : f.items) {
      Sphere s = world_sphere(item.mesh->bounding_sphere(), item.world);
      far = std::max(far, -view.transform_point(s.center).z + s.radius);
    }
    f.camera.far = std::max(far * 1.01f + 1e-3f, f.camera.near * 2);
    if (cam.perspective()) check_depth_precision(cam.znear, f.camera.far, "the scene's depth (zfar None: the farthest mesh)");
  }
  cam.apply(f.camera, width, height);
  f.start.color = {float(scene.bg_color[0]), float(scene.bg_color[1]), float(scene.bg_color[2]),
                   float(scene.bg_color[3])};
  return f;
}

RenderOutput render_frame(Renderer& r, const SceneCopy& frame, const RenderRequest& req) {
  const int w = r.width(), h = r.height();
  const size_t pixels = size_t(w) * size_t(h);
  RenderOptions saved = r.options;
  r.options.object_ids = req.mask;
  r.options.shading = req.shading;
  r.options.cull_back_faces = req.cull_back_faces;
  r.options.normals = req.normals;
  if (req.color_pipeline) r.options.color = *req.color_pipeline;
  // A light casts a shadow when it may (its cast_shadows) and the renderer has shadows
  // on, or the frame's flags name its type.
  r.options.shadows = saved.shadows || req.shadows_directional || req.shadows_point || req.shadows_spot;
  std::vector<Light> lights = frame.lights;
  RenderOutput out;
  for (Light& l : lights) {
    const bool flagged = (l.type == LightType::Directional && req.shadows_directional) ||
                         (l.type == LightType::Point && req.shadows_point) ||
                         (l.type == LightType::Spot && req.shadows_spot);
    l.cast_shadows = l.type != LightType::Ambient && l.cast_shadows && (saved.shadows || flagged);
    out.cast_shadows.push_back(l.cast_shadows);
  }
  out.options = r.options;
  try {
    r.begin_frame(frame.camera, lights, frame.start);
    for (const SceneCopy::Item& item : frame.items) r.draw(*item.mesh, item.world, nullptr, item.id);
    r.end_frame();
    if (req.color) r.read_color(req.color_buffer, size_t(w) * (req.alpha ? 4 : 3), req.alpha ? 4 : 3);
    float* depth = req.depth_buffer;
    if (!depth) {
      out.depth.resize(pixels);
      depth = out.depth.data();
    }
    r.read_view_depth(depth);
    if (req.mask) out.mask = r.object_ids();
    if (req.normals) {
      out.normals.resize(pixels * 3);
      r.read_normals(out.normals.data());
    }
  } catch (...) {
    r.options = saved;
    throw;
  }
  r.options = saved;
  return out;
}

std::unique_ptr<uint8_t[]> BufferPool::take(size_t bytes) {
  {
    std::lock_guard lock(mutex_);
    if (bytes == bytes_ && !free_.empty()) {
      std::unique_ptr<uint8_t[]> b = std::move(free_.back());
      free_.pop_back();
      return b;
    }
  }
  return std::unique_ptr<uint8_t[]>(new uint8_t[bytes]);  // uninitialised: read_color fills it
}

void BufferPool::give(std::unique_ptr<uint8_t[]> buffer, size_t bytes) {
  std::lock_guard lock(mutex_);
  if (bytes != bytes_) free_.clear(), bytes_ = bytes;  // the renderer was resized
  if (free_.size() < 4) free_.push_back(std::move(buffer));  // colour and depth, two frames
}

}  // namespace velocity::python
