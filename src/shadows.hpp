// The frame's shadow maps: which lights get one, and the views they are rendered from
// (docs/appearance.md, "Shadows"). The frame (frame.cpp) renders each view's depth with
// its own pipeline at shadow_map_size a side; the lighting model reads them
// (shading/shadow.hpp).
#pragma once

#include <vector>

#include "shading/shadow.hpp"
#include "velocity/math.hpp"
#include "velocity/mesh.hpp"
#include "velocity/scene.hpp"

namespace velocity {

// One depth image to render: world to the light's view, and its projection.
struct ShadowView {
  Mat4 view, projection;
  bool orthographic = false;
};

// A light with a shadow: which light of the frame's EyeLights it is (a directional or
// a point/spot one, by index in that list), its views (1, or a point light's 6 cube
// faces) and its maps as the lighting reads them, all but the depth pointers filled.
struct ShadowLight {
  bool directional = false;
  size_t index = 0;
  int faces = 0;
  ShadowView views[6];
  shading::LightShadow shadow;
};

// The lights of `lights` that cast shadows (at most shading::kShadowLights, the first
// ones), with views fitted to `bounds` (the casters' bounding sphere, world space):
// directional, an orthographic box around it; spot, a perspective frustum over the outer
// cone; point, a cube of 90-degree frusta along the eye-space axes. `camera_view` is
// the frame's world-to-eye matrix, `size` the maps' side.
void plan_shadows(const std::vector<Light>& lights, const Mat4& camera_view, Sphere bounds, int size,
                  std::vector<ShadowLight>& out);

// The world bounding sphere of a mesh drawn with `world` (scaled by its largest axis).
Sphere world_bounds(const Mesh& mesh, const Mat4& world);

// The smallest sphere (near enough) holding `a` and `b`; a radius below 0 is empty.
Sphere merge_bounds(Sphere a, Sphere b);

}  // namespace velocity
