// `velocity view`: an orbit viewer. Left-drag rotates about the model, the wheel zooms,
// right-drag pans; keys switch shading, wireframe, painter's / depth buffer, SSAA,
// affine / perspective textures, back faces, and take screenshots; a glTF file's
// animation plays (pause, step). A file dropped on the window replaces the model.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "runtime/program.hpp"
#include "velocity/animation.hpp"
#include "velocity/load.hpp"
#include "velocity/renderer.hpp"

namespace velocity::realtime {

struct ViewerOptions {
  std::string model;          // empty: the demo scene
  LoadOptions load;
  bool cull_back_faces = false;
  std::string screenshot_prefix = "velocity-shot";  // screenshots: PREFIX-NNN.png
  int ssaa = 1;
  // The colour pipeline, tone mapping and exposure, as `render` takes them
  // (docs/appearance.md): Auto is linear with sRGB for PBR materials (glTF).
  ColorPipeline color = ColorPipeline::Auto;
  ToneMap tone_map = ToneMap::None;
  float exposure = 1.0f;
  bool shadows = false;  // to start with (O toggles)
  int shadow_map_size = 2048;
};

class ViewerProgram : public Program {
 public:
  // Throws velocity::Error when the model cannot be loaded.
  explicit ViewerProgram(ViewerOptions options);
  void resize(int width, int height) override;
  void event(const InputEvent& e, const InputState& input) override;
  void update(double dt, const InputState& input) override;
  void frame(FrameDescription& out) override;
  bool finished() const override { return quit_; }
  bool changed() const override { return changed_; }
  std::string title() const override;

  // The orbit, for tests: angles in radians, distance in scene units.
  float yaw() const { return yaw_; }
  float pitch() const { return pitch_; }
  float distance() const { return distance_; }
  const Scene& scene() const { return scene_; }
  bool grid_shown() const { return show_grid_; }
  bool axes_shown() const { return show_axes_; }
  const RenderOptions& render_options() const { return options_; }
  const std::string& message() const { return message_; }
  size_t points() const { return points_; }
  // The model's animations (one plays, looping: the first, N the next), the time into it,
  // and whether it is playing (K pauses and plays, J / L step a tenth of a second back / on).
  const std::vector<Animation>& animations() const { return animations_; }
  size_t animation() const { return anim_; }
  double animation_time() const { return anim_time_; }
  bool playing() const { return playing_; }
  // The direction towards the key light (the first directional one); zero if none.
  Vec3 light_direction() const {
    for (const Light& l : scene_.lights)
      if (l.type == LightType::Directional) return normalize(l.direction);
    return {};
  }

 private:
  void open(const std::string& path);  // throws
  void reset_view();
  void seek(double t);
  std::string animation_label() const;
  void place_camera();
  Light* key_light();  // the first directional light (Shift+drag turns it); null if none

  ViewerOptions o_;
  Scene scene_;
  std::string name_;
  size_t triangles_ = 0, points_ = 0;  // points: triangles (v, v, v) of a point cloud
  Vec3 target_, initial_dir_{0.6f, 0.45f, 1.0f};
  Vec3 home_target_;           // the opening view, which R returns to
  float home_distance_ = 3;
  std::shared_ptr<const Mesh> grid_;  // G: lines on the floor under the model, built on open
  Vec3 grid_at_;
  float grid_step_ = 1;
  std::shared_ptr<const Mesh> axes_[3];  // X: the world's axes at its origin, red, green, blue
  float radius_ = 1, yaw_ = 0, pitch_ = 0, distance_ = 3;
  RenderOptions options_;
  int shading_ = 0;  // 0: the model's own; then flat, gouraud, phong, unlit, points
  bool wire_ = false, help_ = false, spin_ = false, quit_ = false, show_grid_ = false, show_axes_ = false;
  int drag_ = 0, last_x_ = 0, last_y_ = 0;
  int shots_ = 0;
  std::string pending_shot_;
  bool shot_overlay_ = false;
  std::string message_;
  bool changed_ = true;  // something to draw since the last frame
  double message_time_ = 0;
  std::vector<Animation> animations_;
  double anim_time_ = 0;
  size_t anim_ = 0;  // the one playing
  std::vector<Skin> skins_;  // posed after each step of the animation
  bool playing_ = true;
};

}  // namespace velocity::realtime
