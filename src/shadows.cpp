// Which lights get a shadow map and the views they are rendered from (shadows.hpp).
#include "shadows.hpp"

#include <algorithm>
#include <cmath>

namespace velocity {

namespace {

// An up vector that is not parallel to `forward`.
Vec3 up_for(Vec3 forward) { return std::fabs(forward.y) > 0.99f ? Vec3{0, 0, 1} : Vec3{0, 1, 0}; }

// A perspective view from `at` along `forward` (both eye space) over `bounds` (eye
// space): near and far hug the sphere, the near plane no closer than far / 1000 so that
// the depth keeps its precision.
void perspective_view(Vec3 at, Vec3 forward, float fov, Sphere bounds, const Mat4& camera_view, int size,
                      ShadowView& v, shading::ShadowMap& m) {
  const float dist = length(bounds.center - at);
  const float far = std::max(dist + bounds.radius, 1e-3f) * 1.01f;
  const float near = std::max(dist - bounds.radius, far * 1e-3f);
  const Mat4 light = look_at(at, at + forward, up_for(forward));  // eye space to the light's
  v.view = light * camera_view;
  v.projection = perspective(fov, 1.0f, near, far);
  v.orthographic = false;
  m.eye_to_clip = v.projection * light;
  m.perspective = true;
  m.near = near, m.far = far;
  m.code_scale = shading::kShadowFar / (far - near), m.code_offset = -near * m.code_scale;
  m.texel = 2.0f * std::tan(fov * 0.5f) / float(size);
}

}  // namespace

Sphere world_bounds(const Mesh& mesh, const Mat4& world) {
  const Bounds b = mesh.bounds();
  float stretch = 0;
  for (int c = 0; c < 3; ++c) stretch = std::max(stretch, length({world.m[0][c], world.m[1][c], world.m[2][c]}));
  return {world.transform_point(b.center()), 0.5f * length(b.max - b.min) * stretch};
}

Sphere merge_bounds(Sphere a, Sphere b) {
  if (a.radius < 0) return b;
  if (b.radius < 0) return a;
  const float d = length(b.center - a.center);
  if (d + b.radius <= a.radius) return a;
  if (d + a.radius <= b.radius) return b;
  const float r = 0.5f * (d + a.radius + b.radius);
  return {a.center + (b.center - a.center) * ((r - a.radius) / d), r};
}

void plan_shadows(const std::vector<Light>& lights, const Mat4& camera_view, Sphere bounds, int size,
                  std::vector<ShadowLight>& out) {
  out.clear();
  if (!(bounds.radius >= 0) || !std::isfinite(bounds.radius)) return;
  // Eye space (the camera's view is rigid: the radius is kept).
  bounds = {camera_view.transform_point(bounds.center), std::max(bounds.radius, 1e-3f)};
  size_t directional = 0, point = 0;  // the EyeLights index of each kind, as eye_lights counts
  for (const Light& l : lights) {
    if (l.type == LightType::Ambient) continue;
    const bool is_directional = l.type == LightType::Directional;
    const size_t index = is_directional ? directional++ : point++;
    if (!l.cast_shadows || out.size() == size_t(shading::kShadowLights)) continue;
    ShadowLight s;
    s.directional = is_directional, s.index = index;
    shading::LightShadow& sh = s.shadow;
    if (is_directional) {
      // An orthographic box around the casters, seen from the light's side.
      const Vec3 to_light = normalize(camera_view.transform_vector(l.direction));
      const float r = bounds.radius;
      const Vec3 at = bounds.center + to_light * (2.0f * r);
      const Mat4 light = look_at(at, bounds.center, up_for(-to_light));
      s.views[0] = {light * camera_view, orthographic(-r, r, -r, r, 0.5f * r, 3.5f * r), true};
      sh.face[0].eye_to_clip = s.views[0].projection * light;
      sh.face[0].texel = 2.0f * r / float(size);
      s.faces = 1;
    } else if (l.type == LightType::Spot) {
      const Vec3 at = camera_view.transform_point(l.position);
      const Vec3 axis = normalize(camera_view.transform_vector(-l.direction));
      // The cone, and a texel's margin so that the filter at its edge stays inside.
      const float fov = std::min(2.0f * l.outer_cone * (1.0f + 2.0f / float(size)) + 1e-3f, radians(170.0f));
      perspective_view(at, axis, fov, bounds, camera_view, size, s.views[0], sh.face[0]);
      s.faces = 1;
    } else {
      const Vec3 at = camera_view.transform_point(l.position);
      const Vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      for (int f = 0; f < 6; ++f) perspective_view(at, axes[f], radians(90.0f), bounds, camera_view, size, s.views[f], sh.face[f]);
      sh.position = at;
      s.faces = 6;
    }
    sh.faces = s.faces;
    for (int f = 0; f < s.faces; ++f) sh.face[f].size = size, sh.face[f].stride = shading::shadow_stride(size);
    out.push_back(s);
  }
}

}  // namespace velocity
