// The scene: objects in a parent/child hierarchy, a camera and lights.
//
// Seed 000's engine calls map onto this API one to one (see docs/api.md):
//   LoadCar(file)             -> load_model(file) + Scene::add_object
//   ScaleCar(x, y, z)         -> object.transform.scale = {x, y, z}
//   MoveCar(rx, ry, rz, ...)  -> object.transform.rotation / .translation
//   Reset_Car                 -> object.transform = {}
//   Set_Camera_Position(...)  -> scene.camera.position / pitch / yaw / roll / fov
//   DrawCar                   -> Renderer::render(scene)
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "velocity/material.hpp"
#include "velocity/math.hpp"
#include "velocity/mesh.hpp"

namespace velocity {

// Scale, then rotate (roll about Z, pitch about X, yaw about Y, in that order), then
// translate: M = T * Ry * Rx * Rz * S. Angles in radians. The mesh itself is untouched.
struct Transform {
  Vec3 scale{1, 1, 1};
  Vec3 rotation;  // x = pitch, y = yaw, z = roll
  Vec3 translation;

  Mat4 matrix() const;
};

using ObjectId = uint32_t;
inline constexpr ObjectId kNoParent = UINT32_MAX;

struct Object {
  std::string name;
  std::shared_ptr<const Mesh> mesh;  // may be null: a pure transform node
  Transform transform;               // relative to the parent
  ObjectId parent = kNoParent;
  bool visible = true;
  // When set, replaces the mesh's own materials and face colours.
  std::optional<Material> material;
  // Applied before `transform` (a file's own node matrix, say): world = parent *
  // transform.matrix() * base.
  Mat4 base;
};

enum class Projection { Perspective, Orthographic };

// The view volume's cross-section, left < right and bottom < top: for a perspective
// camera on the plane one unit in front of it (a centred camera with vertical field of
// view f has top = tan(f / 2)), for an orthographic one in world units. Off-centre
// windows are allowed: a shifted lens, or a pinhole camera's principal point.
struct ViewWindow {
  float left = -1, right = 1, bottom = -1, top = 1;

  // The window of a pinhole camera with focal lengths fx, fy and principal point cx, cy
  // in pixels, for a width x height image. Image coordinates run right and down from
  // the image's top-left corner, and pixel (i, j) covers [i, i + 1] x [j, j + 1], so its
  // centre is at (i + 0.5, j + 0.5) (OpenGL's and pyrender's convention; OpenCV puts
  // pixel centres on whole numbers: add 0.5 to its cx and cy). Throws velocity::Error
  // unless fx, fy > 0, width, height >= 1 and all are finite.
  static ViewWindow pinhole(float fx, float fy, float cx, float cy, int width, int height);
};

// A camera at `position` turned by yaw (about Y), then pitch (about X), then roll
// (about Z), looking down its own -Z axis: seed 000's swivel, pitch and roll.
struct Camera {
  Vec3 position{0, 0, 3};
  float pitch = 0, yaw = 0, roll = 0;  // radians
  Projection projection = Projection::Perspective;
  float fov_y = radians(45.0f);  // vertical field of view (perspective)
  float ortho_height = 2.0f;     // height of the view volume (orthographic)
  float near = 0.1f, far = 100.0f;
  // When set, the view volume's cross-section (see ViewWindow), replacing fov_y or
  // ortho_height and the image's aspect ratio.
  std::optional<ViewWindow> window;

  // Field of view of a lens of `focal_mm` on film `film_height_mm` high (seed 000's
  // focal length; 3D Studio's cameras use 35 mm film, 24 mm high).
  static float fov_from_focal_length(float focal_mm, float film_height_mm = 24.0f);

  // Turns the camera (yaw and pitch, roll kept) to look at `target`.
  void look_at(Vec3 target);
  Mat4 view() const;
  // As glFrustum / glOrtho: from `window` when set (aspect unused), else centred with
  // fov_y (perspective) or ortho_height (orthographic) and the given width / height.
  Mat4 projection_matrix(float aspect) const;
};

enum class LightType { Ambient, Directional, Point, Spot };

// How a point or spot light's intensity falls with distance d: the seed's and OpenGL's
// 1 / (c + l*d + q*d^2), or KHR_lights_punctual's physical inverse square windowed by
// `range` (clamp(1 - (d/range)^4, 0, 1)^2 / d^2; range 0 is infinite).
enum class Falloff { Attenuation, InverseSquare };

struct Light {
  LightType type = LightType::Directional;
  Vec3 color{1, 1, 1};  // intensity per channel (PBR: linear; lux for directional, candela for point/spot)
  // Directional and spot: the direction *towards* the light (the opposite of where a spot
  // points), in world space.
  Vec3 direction{0, 0, 1};
  // Point and spot: position in world space, attenuation 1 / (c + l*d + q*d^2).
  Vec3 position;
  float constant = 1, linear = 0, quadratic = 0;
  Falloff falloff = Falloff::Attenuation;
  float range = 0;
  // Spot: full intensity inside inner_cone, none outside outer_cone (half-angles in
  // radians, 0 <= inner < outer <= pi/2), KHR_lights_punctual's smooth falloff between.
  float inner_cone = 0, outer_cone = radians(45.0f);
  // Casts shadows when the frame's shadows are on (RenderOptions).
  bool cast_shadows = true;

  static Light ambient(Vec3 color) {
    Light l;
    l.type = LightType::Ambient;
    l.color = color;
    return l;
  }
  static Light directional(Vec3 towards, Vec3 color) {
    Light l;
    l.color = color;
    l.direction = normalize(towards);
    return l;
  }
  static Light spot(Vec3 position, Vec3 towards, Vec3 color, float inner_cone, float outer_cone) {
    Light l;
    l.type = LightType::Spot;
    l.color = color;
    l.position = position;
    l.direction = normalize(towards);
    l.inner_cone = inner_cone;
    l.outer_cone = outer_cone;
    return l;
  }
  static Light point(Vec3 position, Vec3 color, float linear = 0, float quadratic = 0) {
    Light l;
    l.type = LightType::Point;
    l.color = color;
    l.position = position;
    l.linear = linear;
    l.quadratic = quadratic;
    return l;
  }
};

// The convention's light, defined here once: white from `towards` (unit length after
// normalising) with ambient 0.2 and diffuse 0.8. The renderer lights a frame that brings
// no lights with it in eye space; a viewer adds it to a scene that has no key light
// (Light::ambient(kDefaultLight.ambient), Light::directional(kDefaultLight.towards,
// kDefaultLight.diffuse)).
struct DefaultLight {
  Vec3 towards, ambient, diffuse;
};
inline constexpr DefaultLight kDefaultLight{{0.3f, 0.5f, 1.0f}, {0.2f, 0.2f, 0.2f}, {0.8f, 0.8f, 0.8f}};

class Scene {
 public:
  // Adds an object. A parent must already exist, so objects are always stored parents
  // first and world matrices are computed in one pass. Throws velocity::Error for an
  // unknown parent.
  ObjectId add_object(std::string name, std::shared_ptr<const Mesh> mesh, ObjectId parent = kNoParent);
  Object& object(ObjectId id) { return objects_.at(id); }
  const Object& object(ObjectId id) const { return objects_.at(id); }
  const std::vector<Object>& objects() const { return objects_; }
  // The first object called `name`, if any.
  std::optional<ObjectId> find(std::string_view name) const;

  // Object-to-world matrix of every object (parent chain applied), indexed by ObjectId.
  std::vector<Mat4> world_matrices() const;
  // The same into `out` (resized; no allocation once it is large enough).
  void world_matrices(std::vector<Mat4>& out) const;
  // Bounding sphere of every visible mesh in world space (radius 0 when empty).
  Sphere bounds() const;
  // Places the camera in direction `from` (default +Z) of the scene's bounding-sphere
  // centre, looking at it, so that the whole scene fits the field of view; near and far
  // are set around it.
  void frame_camera(float aspect, Vec3 from = {0, 0, 1});

  Camera camera;
  std::vector<Light> lights;
  Vec3 background{0.1f, 0.1f, 0.15f};

 private:
  std::vector<Object> objects_;
};

}  // namespace velocity
