#include "velocity/view_setup.hpp"

#include <algorithm>

namespace velocity {

void make_two_sided(Model& model) {
  for (ModelNode& node : model.nodes) {
    if (!node.mesh) continue;
    if (node.mesh->materials.empty()) node.mesh->materials.emplace_back();
    for (Material& m : node.mesh->materials) m.two_sided = true;
  }
}

void add_default_lights(Scene& scene) {
  bool has_key = std::any_of(scene.lights.begin(), scene.lights.end(),
                             [](const Light& l) { return l.type != LightType::Ambient; });
  if (has_key) return;
  // The convention's light (kDefaultLight) as scene lights, fixed in the world: the side
  // of the model it lights stays lit as the camera orbits.
  if (scene.lights.empty()) scene.lights.push_back(Light::ambient(kDefaultLight.ambient));
  scene.lights.push_back(Light::directional(kDefaultLight.towards, kDefaultLight.diffuse));
}

Scene scene_from_model(const std::string& path, const LoadOptions& options, bool cull_back_faces, float aspect,
                       std::vector<Animation>* animations, std::vector<Skin>* skins) {
  Model model = load_model(path, options);
  if (!cull_back_faces) make_two_sided(model);
  Scene scene;
  add_to_scene(scene, model);  // node i is object i: the scene was empty
  if (animations) *animations = std::move(model.animations);
  if (skins) {
    skin(model.skins, scene);
    *skins = std::move(model.skins);
  }
  add_default_lights(scene);
  scene.frame_camera(aspect, Vec3{0.6f, 0.45f, 1.0f});
  return scene;
}

std::string explain_empty_frame(const FrameStats& s, bool cull_back_faces) {
  if (s.triangles_rasterized > 0 || s.lines > 0 || s.points > 0) return "";
  if (s.objects == 0 || s.triangles == 0) return "the scene has no triangles to draw";
  if (s.objects_culled >= s.objects) return "every object is outside the camera's view (move the camera)";
  size_t left = s.triangles - std::min(s.triangles, s.triangles_rejected + s.triangles_nonfinite);
  if (left == 0) {
    if (s.triangles_nonfinite >= s.triangles) return "every triangle has a NaN or infinite coordinate";
    return "every triangle is outside the camera's view (move the camera)";
  }
  if (cull_back_faces)
    return "every triangle in view faces away from the camera and back faces are culled "
           "(an open mesh seen from behind: draw back faces, the default without --cull, or move the camera)";
  return "no triangle covers a pixel centre (the model is too small or too thin at this image size)";
}

}  // namespace velocity
