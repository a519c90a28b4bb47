#include "velocity/demo.hpp"

#include <memory>

#include "velocity/texture.hpp"

namespace velocity {

namespace {

Material material(Vec3 color, Shading shading, float specular = 0.0f, float shininess = 32.0f) {
  Material m;
  m.color = color;
  m.shading = shading;
  m.specular = specular;
  m.shininess = shininess;
  return m;
}

ObjectId add(Scene& scene, const char* name, std::shared_ptr<const Mesh> mesh, Material m, Vec3 at,
             ObjectId parent = kNoParent) {
  ObjectId id = scene.add_object(name, std::move(mesh), parent);
  scene.object(id).material = std::move(m);
  scene.object(id).transform.translation = at;
  return id;
}

// A cube whose corners carry red, green, blue, ... : seed 002's colour gradient.
std::shared_ptr<Mesh> gradient_cube() {
  auto cube = std::make_shared<Mesh>(make_cube(1.0f));
  for (Vec3 p : cube->positions) cube->colors.push_back({p.x + 0.5f, p.y + 0.5f, p.z + 0.5f});
  return cube;
}

}  // namespace

Scene make_demo_scene(float time) {
  Scene scene;
  auto sphere = std::make_shared<Mesh>(make_sphere(32));
  for (Vec3& p : sphere->positions) p = p * 0.72f;  // fits the 1.6-unit spacing of the row
  auto torus = std::make_shared<const Mesh>(make_torus(0.55f, 0.22f, 48, 24));
  auto cube = std::make_shared<const Mesh>(make_cube(1.0f));
  auto floor = std::make_shared<const Mesh>(make_plane_grid(14.0f, 14));
  // Every texture is generated: nothing to ship, nothing to download.
  auto checker = std::make_shared<const Texture>(make_checkerboard(256, 32));
  auto studio = std::make_shared<const Texture>(make_environment_map(256));

  add(scene, "floor", floor, material({0.35f, 0.38f, 0.42f}, Shading::Gouraud), {0, -0.75f, 0});

  // Front row, left to right: flat, Gouraud, Phong with a highlight, textured,
  // environment-mapped (per vertex), Phong + environment map (per pixel).
  const float row = 0.0f;
  add(scene, "flat sphere", sphere, material({0.85f, 0.35f, 0.3f}, Shading::Flat), {-4.0f, 0, row});
  ObjectId t = add(scene, "gouraud torus", torus, material({0.3f, 0.75f, 0.4f}, Shading::Gouraud), {-2.4f, 0, row});
  scene.object(t).transform.rotation = {radians(60), 0, 0};
  add(scene, "phong sphere", sphere, material({0.3f, 0.45f, 0.9f}, Shading::Phong, 0.6f, 48), {-0.8f, 0, row});
  Material textured = material({1, 1, 1}, Shading::Gouraud);
  textured.texture = checker;
  ObjectId tc = add(scene, "textured cube", cube, textured, {0.8f, 0, row});
  scene.object(tc).transform.rotation = {radians(25), radians(35 + time * 20), 0};
  Material env = material({1, 1, 1}, Shading::Gouraud);
  env.env_map = studio;
  add(scene, "env sphere", sphere, env, {2.4f, 0, row});
  Material chrome = material({0.9f, 0.9f, 0.9f}, Shading::Phong, 0.8f, 64);
  chrome.env_map = studio;
  ObjectId ct = add(scene, "chrome torus", torus, chrome, {4.0f, 0, row});
  scene.object(ct).transform.rotation = {radians(70), 0, radians(20)};

  // Back row: vertex colours (seed 002's gradient) and wireframe.
  ObjectId c = add(scene, "gradient cube", gradient_cube(), material({1, 1, 1}, Shading::Unlit), {-1.2f, 0, -2.6f});
  scene.object(c).transform.rotation = {radians(25), radians(35), 0};
  scene.object(c).material.reset();  // use the cube's own vertex colours
  add(scene, "wire sphere", sphere, material({0.9f, 0.9f, 0.9f}, Shading::Wireframe), {1.2f, 0, -2.6f});

  // The car: a checkered, environment-mapped shell with Phong highlights (seed 000's
  // car), a glassy cabin, and four wheels as children.
  Material shell = material({0.95f, 0.8f, 0.25f}, Shading::Phong, 0.6f, 48);
  shell.texture = checker;
  shell.env_map = studio;
  shell.env_mix = 0.35f;
  ObjectId car = add(scene, "car", cube, shell, {0, -0.25f, 2.6f});
  scene.object(car).transform.scale = {2.0f, 0.5f, 1.0f};
  scene.object(car).transform.rotation = {0, 0.4f + time * 0.5f, 0};
  // Children live in the body's space, which is scaled: undo the scale for the parts.
  Material glass = material({0.2f, 0.25f, 0.3f}, Shading::Phong, 0.9f, 96);
  glass.env_map = studio;
  glass.env_mix = 0.5f;
  ObjectId cabin = add(scene, "cabin", cube, glass, {-0.1f, 0.8f, 0}, car);
  scene.object(cabin).transform.scale = {0.5f, 0.8f, 0.8f};
  const Vec3 wheel_at[4] = {{-0.32f, -0.5f, 0.5f}, {0.32f, -0.5f, 0.5f}, {-0.32f, -0.5f, -0.5f}, {0.32f, -0.5f, -0.5f}};
  auto tyre = std::make_shared<const Mesh>(make_torus(0.6f, 0.35f, 12, 6));
  for (int i = 0; i < 4; ++i) {
    // A mesh-less mount stands the wheel up (torus axis along the axle, Z) and undoes
    // the body's scale; the wheel under it spins about its own axis.
    ObjectId mount = scene.add_object("wheel mount", nullptr, car);
    scene.object(mount).transform.translation = wheel_at[i];
    // Mount space: S first, then Rx(90) turns z into -y, then the body scales (2, 0.5, 1).
    scene.object(mount).transform.scale = {0.3f / 2.0f, 0.3f, 0.3f / 0.5f};
    scene.object(mount).transform.rotation = {radians(90), 0, 0};
    ObjectId w = add(scene, "wheel", tyre, material({0.15f, 0.15f, 0.17f}, Shading::Flat), {}, mount);
    scene.object(w).transform.rotation = {0, -time * 3.0f, 0};
  }

  scene.lights.push_back(Light::ambient({0.2f, 0.2f, 0.2f}));
  scene.lights.push_back(Light::directional({0.3f, 0.6f, 1.0f}, {0.7f, 0.7f, 0.7f}));
  scene.lights.push_back(Light::point({2.0f, 2.5f, 3.0f}, {0.5f, 0.45f, 0.4f}, 0.0f, 0.05f));

  scene.camera.position = {0, 2.8f, 8.5f};
  scene.camera.fov_y = radians(50);
  scene.camera.look_at({0, 0, 0.2f});
  return scene;
}

}  // namespace velocity
