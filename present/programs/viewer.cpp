#include "programs/viewer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <vector>

#include "programs/shapes.hpp"
#include "velocity/demo.hpp"
#include "velocity/error.hpp"
#include "velocity/view_setup.hpp"

namespace velocity::realtime {

namespace {

constexpr Shading kShadings[] = {Shading::Flat, Shading::Gouraud, Shading::Phong, Shading::Unlit, Shading::Points};
constexpr float kPi = std::numbers::pi_v<float>;

std::string upper(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = char(std::toupper(static_cast<unsigned char>(c)));
  return r;
}

// A square grid of `lines` x `lines` lines `step` apart in the XZ plane, centred on the
// origin, as thin flat strips (unlit grey, seen from both sides).
Mesh make_floor_grid(int lines, float step) {
  Mesh m;
  m.name = "viewer grid";
  Material mat;
  mat.name = "grid";
  mat.color = {0.55f, 0.6f, 0.65f};
  mat.shading = Shading::Unlit;
  mat.two_sided = true;
  m.materials.push_back(mat);
  const float half = step * float(lines - 1) / 2, w = step * 0.02f;
  auto strip = [&](Vec3 a, Vec3 b, Vec3 side) {
    uint32_t base = uint32_t(m.positions.size());
    for (Vec3 p : {a - side, a + side, b + side, b - side}) m.positions.push_back(p);
    m.triangles.push_back({{base, base + 1, base + 2}});
    m.triangles.push_back({{base, base + 2, base + 3}});
  };
  for (int i = 0; i < lines; ++i) {
    float t = -half + step * float(i);
    strip({t, 0, -half}, {t, 0, half}, {w, 0, 0});
    strip({-half, 0, t}, {half, 0, t}, {0, 0, w});
  }
  m.face_materials.assign(m.triangles.size(), 0);
  compute_normals(m);
  return m;
}

// An axis: a thin box from the origin `length` along axis `a` (0 X, 1 Y, 2 Z), unlit.
Mesh make_axis(int a, float length, Vec3 color) {
  const float t = length * 0.015f;
  Mesh m = make_shaped_box([&](Vec3 p) {
    Vec3 q{p.x * 2 * t, p.y * 2 * t, p.z * 2 * t};
    (&q.x)[a] = ((&p.x)[a] + 0.5f) * length;
    return q;
  });
  Material mat;
  mat.name = "axis";
  mat.color = color;
  mat.shading = Shading::Unlit;
  m.materials = {mat};
  m.face_colors.clear();
  m.face_materials.assign(m.triangles.size(), 0);
  return m;
}

}  // namespace

ViewerProgram::ViewerProgram(ViewerOptions options) : o_(std::move(options)) {
  options_.ssaa = std::clamp(o_.ssaa, 1, 3);  // what A cycles through
  options_.shadows = o_.shadows;
  options_.shadow_map_size = o_.shadow_map_size;
  options_.cull_back_faces = true;  // materials decide: loaded models are two-sided (see velocity/view_setup.hpp)
  options_.color = o_.color, options_.tone_map = o_.tone_map, options_.exposure = o_.exposure;
  open(o_.model);
}

void ViewerProgram::open(const std::string& path) {
  Scene scene;
  std::vector<Animation> animations;
  std::vector<Skin> skins;
  if (path.empty()) {
    scene = make_demo_scene();
    name_ = "DEMO SCENE";
  } else {
    scene = scene_from_model(path, o_.load, o_.cull_back_faces, float(width_) / float(height_), &animations, &skins);
    name_ = std::filesystem::path(path).filename().string();
  }
  triangles_ = points_ = 0;
  for (const Object& obj : scene.objects())
    if (obj.mesh)
      for (const Triangle& t : obj.mesh->triangles) {
        const bool point = t.v[0] == t.v[1] && t.v[1] == t.v[2];
        points_ += point, triangles_ += !point;
      }
  Sphere b = scene.bounds();
  home_target_ = b.center;
  radius_ = std::max(b.radius, 1e-3f);
  // Start where the scene's own camera is (the demo's, or the framed one), orbiting the
  // middle of the scene; without one, far enough to see all of it.
  Vec3 d = scene.camera.position - home_target_;
  if (length(d) > 1e-6f) {
    initial_dir_ = normalize(d);
    home_distance_ = std::max(length(d), radius_ * 0.1f);
  } else {
    home_distance_ = radius_ / std::sin(scene.camera.fov_y / 2) * 1.05f;
  }
  // The grid: under the lowest point of the scene, 1, 2 or 5 times a power of ten apart,
  // about eight lines across the model.
  float low = b.center.y - radius_;
  std::vector<Mat4> world = scene.world_matrices();
  bool any = false;
  for (size_t i = 0; i < scene.objects().size(); ++i) {
    const Object& obj = scene.objects()[i];
    if (!obj.mesh) continue;
    for (const Vec3& p : obj.mesh->positions) {
      float y = world[i].transform_point(p).y;
      low = any ? std::min(low, y) : y;
      any = true;
    }
  }
  float raw = radius_ / 4, decade = std::pow(10.0f, std::floor(std::log10(raw)));
  grid_step_ = decade * (raw / decade < 2 ? 1.0f : raw / decade < 5 ? 2.0f : 5.0f);
  // (A hair above it: a floor in the scene would otherwise fight it for the pixels.)
  grid_at_ = {std::round(b.center.x / grid_step_) * grid_step_, low + radius_ * 0.002f,
              std::round(b.center.z / grid_step_) * grid_step_};
  grid_ = std::make_shared<const Mesh>(make_floor_grid(2 * int(std::ceil(radius_ * 1.5f / grid_step_)) + 1, grid_step_));
  const Vec3 axis_colors[3] = {{0.9f, 0.15f, 0.1f}, {0.2f, 0.85f, 0.2f}, {0.2f, 0.4f, 1.0f}};
  for (int a = 0; a < 3; ++a) axes_[a] = std::make_shared<const Mesh>(make_axis(a, radius_ * 0.6f, axis_colors[a]));
  scene_ = std::move(scene);
  animations_ = std::move(animations);
  skins_ = std::move(skins);
  anim_time_ = 0;
  anim_ = 0;
  playing_ = true;
  if (!animations_.empty()) apply(animations_[0], 0.0f, scene_);
  skin(skins_, scene_);
  reset_view();
}

// Moves the animation to `t` (wrapped into its length: it loops) and poses the scene.
void ViewerProgram::seek(double t) {
  if (animations_.empty()) return;
  const double length = animations_[anim_].duration;
  anim_time_ = length > 0 ? t - std::floor(t / length) * length : 0.0;
  apply(animations_[anim_], float(anim_time_), scene_);
  skin(skins_, scene_);  // the joints moved
  changed_ = true;
}

// The animation playing, for the status bar: "2/3 WALK" (its number; its name if it has one).
std::string ViewerProgram::animation_label() const {
  std::string label = std::to_string(anim_ + 1) + "/" + std::to_string(animations_.size());
  if (!animations_[anim_].name.empty()) label += " " + upper(animations_[anim_].name);
  return label;
}

// Back to the opening view: orbit angles, distance, and the pan undone.
void ViewerProgram::reset_view() {
  Vec3 d = initial_dir_;
  yaw_ = std::atan2(d.x, d.z);
  pitch_ = std::asin(std::clamp(d.y, -1.0f, 1.0f));
  target_ = home_target_;
  distance_ = home_distance_;
}

Light* ViewerProgram::key_light() {
  for (Light& l : scene_.lights)
    if (l.type == LightType::Directional) return &l;
  return nullptr;
}

void ViewerProgram::place_camera() {
  Camera& c = scene_.camera;
  Vec3 dir{std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), std::cos(pitch_) * std::cos(yaw_)};
  c.position = target_ + dir * distance_;
  c.roll = 0;
  c.look_at(target_);
  // The depth range around the scene as it is now (an animation moves and grows it).
  const Sphere now = scene_.bounds();
  float to_center = length(now.center - c.position);
  float reach = std::max(radius_, now.radius) * (show_grid_ ? 2.4f : 1.2f);  // the grid reaches past the model
  c.near = std::max(to_center - reach, std::max(distance_, radius_) * 1e-3f);
  c.far = to_center + reach;
}

void ViewerProgram::resize(int width, int height) {
  Program::resize(width, height);
  changed_ = true;
}

void ViewerProgram::event(const InputEvent& e, const InputState& input) {
  auto say = [&](std::string m) {
    message_ = std::move(m);
    message_time_ = 2.5;
  };
  if (e.kind != InputEvent::MouseMove || drag_) changed_ = true;
  switch (e.kind) {
    case InputEvent::MouseDown:
      drag_ = e.button == MouseButton::Left ? (input.held(KeyShift) ? 3 : 1) : 2;
      last_x_ = e.x, last_y_ = e.y;
      if (drag_ == 3) say(key_light() ? "DRAG TO MOVE THE LIGHT" : "NO LIGHT TO MOVE");
      break;
    case InputEvent::MouseUp: drag_ = 0; break;
    case InputEvent::MouseMove:
      if (drag_) {
        float dx = float(e.x - last_x_), dy = float(e.y - last_y_);
        float per_pixel = 1.0f / float(std::max(height_, 1));
        if (drag_ == 1) {
          yaw_ -= dx * per_pixel * kPi;
          pitch_ = std::clamp(pitch_ + dy * per_pixel * kPi, -1.55f, 1.55f);
        } else if (drag_ == 3) {
          // The key light turns as the model would under the mouse: about the vertical,
          // and up or down (never past straight overhead or below).
          if (Light* l = key_light()) {
            Vec3 d = normalize(l->direction);
            float ly = std::atan2(d.x, d.z) + dx * per_pixel * kPi;
            float lp = std::clamp(std::asin(std::clamp(d.y, -1.0f, 1.0f)) - dy * per_pixel * kPi, -1.55f, 1.55f);
            l->direction = {std::cos(lp) * std::sin(ly), std::sin(lp), std::cos(lp) * std::cos(ly)};
          }
        } else {
          // Pan in the view plane, so the point under the mouse follows it.
          const Camera& c = scene_.camera;
          Mat4 v = c.view();
          Vec3 right{v.m[0][0], v.m[0][1], v.m[0][2]}, up{v.m[1][0], v.m[1][1], v.m[1][2]};
          float scale = 2.0f * distance_ * std::tan(c.fov_y / 2) * per_pixel;
          target_ = target_ - right * (dx * scale) + up * (dy * scale);
        }
        last_x_ = e.x, last_y_ = e.y;
      }
      break;
    case InputEvent::Wheel:
      distance_ = std::clamp(distance_ * std::pow(0.88f, e.wheel), radius_ * 0.05f, radius_ * 50.0f);
      break;
    case InputEvent::Drop:
      try {
        open(e.path);
        o_.model = e.path;
        say("OPENED " + upper(name_));
      } catch (const std::exception& ex) {
        say(ex.what());
      }
      break;
    case InputEvent::KeyDown:
      switch (int(e.key)) {
        case KeyEscape:
        case 'q': quit_ = true; break;
        case 's':
          shading_ = (shading_ + 1) % int(std::size(kShadings) + 1);
          say("SHADING " + (shading_ ? upper(to_string(kShadings[shading_ - 1])) : std::string("AS THE MODEL SAYS")));
          break;
        case 'w':
          wire_ = !wire_;
          say(wire_ ? "WIREFRAME" : "SOLID");
          break;
        case 'p':
          options_.depth_mode = options_.depth_mode == DepthMode::ZBuffer ? DepthMode::Painter : DepthMode::ZBuffer;
          say(options_.depth_mode == DepthMode::Painter ? "PAINTER'S ALGORITHM" : "DEPTH BUFFER");
          break;
        case 'a':
          options_.ssaa = options_.ssaa % 3 + 1;
          say("SSAA " + std::to_string(options_.ssaa) + "X" + std::to_string(options_.ssaa));
          break;
        case 'o':
          options_.shadows = !options_.shadows;
          say(options_.shadows ? "SHADOWS" : "NO SHADOWS");
          break;
        case 't':
          options_.affine = !options_.affine;
          say(options_.affine ? "AFFINE TEXTURES" : "PERSPECTIVE-CORRECT TEXTURES");
          break;
        case 'b':
          // Back faces: RenderOptions culls only one-sided materials; two-sided ones
          // (every loaded model's, by default) are drawn unless culling is forced.
          o_.cull_back_faces = !o_.cull_back_faces;
          try {
            if (!o_.model.empty()) open(o_.model);
          } catch (const std::exception& ex) {
            say(ex.what());
            break;
          }
          say(o_.cull_back_faces ? "BACK FACES CULLED" : "BACK FACES DRAWN");
          break;
        case 'r':
          reset_view();
          spin_ = false;
          say("OPENING VIEW");
          break;
        case ' ': spin_ = !spin_; break;
        case 'k':
          if (animations_.empty()) {
            say("NO ANIMATION IN THIS FILE");
            break;
          }
          playing_ = !playing_;
          say(playing_ ? "ANIMATION PLAYING" : "ANIMATION PAUSED");
          break;
        case 'j':
        case 'l':
          // A tenth of a second back or on, paused (a scrub).
          if (animations_.empty()) break;
          playing_ = false;
          seek(anim_time_ + (e.key == Key('l') ? 0.1 : -0.1));
          break;
        case 'n':
          // The next of the file's animations, from its start (the one before at rest).
          if (animations_.size() < 2) {
            say(animations_.empty() ? "NO ANIMATION IN THIS FILE" : "THE FILE HAS ONE ANIMATION");
            break;
          }
          rest(animations_[anim_], scene_);
          anim_ = (anim_ + 1) % animations_.size();
          seek(0);
          say("ANIMATION " + animation_label());
          break;
        case '[':
        case ']':
          // Points are squares this many pixels a side, whatever the super-sampling.
          options_.point_size = std::clamp(options_.point_size + (e.key == Key(']') ? 1.0f : -1.0f), 1.0f, 16.0f);
          say("POINTS " + std::to_string(int(options_.point_size)) + " PIXELS");
          break;
        case 'x':
          show_axes_ = !show_axes_;
          say(show_axes_ ? "AXES: X RED, Y GREEN, Z BLUE" : "NO AXES");
          break;
        case 'g':
          show_grid_ = !show_grid_;
          say(show_grid_ ? "GRID ON THE FLOOR" : "NO GRID");
          break;
        case 'h':
        case KeyF1: help_ = !help_; break;
        case 'c':
        case KeyF12: {
          // The model alone; with Shift, as the window shows it (status bar, messages).
          char name[64];
          std::snprintf(name, sizeof name, "-%03d.png", shots_++);
          pending_shot_ = o_.screenshot_prefix + name;
          shot_overlay_ = input.held(KeyShift);
          break;
        }
        default: break;
      }
      break;
    default: break;
  }
}

void ViewerProgram::update(double dt, const InputState& input) {
  // Moving, or a message on screen (it fades out): the frame changes.
  for (Key k : {KeyLeft, KeyRight, KeyUp, KeyDown, Key('+'), Key('='), Key('-')})
    if (input.held(k)) changed_ = true;
  if (spin_ || message_time_ > 0) changed_ = true;
  if (spin_) yaw_ += float(dt) * 0.6f;
  float turn = float(dt) * 1.5f;
  if (input.held(KeyLeft)) yaw_ -= turn;
  if (input.held(KeyRight)) yaw_ += turn;
  if (input.held(KeyUp)) pitch_ = std::min(pitch_ + turn, 1.55f);
  if (input.held(KeyDown)) pitch_ = std::max(pitch_ - turn, -1.55f);
  if (input.held('+') || input.held('=')) distance_ *= std::pow(0.5f, float(dt));
  if (input.held('-')) distance_ *= std::pow(2.0f, float(dt));
  message_time_ = std::max(0.0, message_time_ - dt);
  if (playing_ && !animations_.empty()) seek(anim_time_ + dt);
  place_camera();
}

std::string ViewerProgram::title() const { return "Velocity - " + name_; }

void ViewerProgram::frame(FrameDescription& out) {
  out.scene = scene_;
  out.options = options_;
  if (wire_) out.options.shading = Shading::Wireframe;
  else if (shading_) out.options.shading = kShadings[shading_ - 1];
  changed_ = false;
  if (show_grid_ && grid_) {
    ObjectId id = out.scene.add_object("viewer grid", grid_);
    out.scene.object(id).transform.translation = grid_at_;
  }
  if (show_axes_) {
    const char* names[3] = {"viewer axis x", "viewer axis y", "viewer axis z"};
    for (int a = 0; a < 3; ++a) out.scene.add_object(names[a], axes_[a]);
  }
  out.screenshot = std::move(pending_shot_);
  out.screenshot_overlay = shot_overlay_;
  pending_shot_.clear();

  const int s = std::max(1, height_ / 300);
  DrawList& d = out.overlay;
  // The status bar: its items left to right, on as many lines as the width needs, the
  // model's name cut to half the width; never past the frame's edges.
  const int room = std::max(width_ - 6 * s, 1);
  std::vector<std::string> items = {
      ellipsize(upper(name_), room / 2, s),
      points_ && !triangles_ ? std::to_string(points_) + " POINTS"
      : points_ ? std::to_string(triangles_) + " TRIANGLES, " + std::to_string(points_) + " POINTS"
                : std::to_string(triangles_) + " TRIANGLES",
      wire_      ? std::string("WIREFRAME")
      : shading_ ? "SHADING: " + upper(to_string(kShadings[shading_ - 1]))
                 : std::string("SHADING: AS THE MODEL SAYS"),
      options_.depth_mode == DepthMode::Painter ? "PAINTER'S ALGORITHM" : "DEPTH BUFFER",
      "SSAA " + std::to_string(options_.ssaa) + "X" + std::to_string(options_.ssaa),
      options_.affine ? "AFFINE TEXTURES" : "PERSPECTIVE TEXTURES",
      options_.shadows ? "SHADOWS" : "NO SHADOWS",
      "H: HELP"};
  if (points_) items.insert(items.end() - 1, "POINTS " + std::to_string(int(options_.point_size)) + " PX");
  if (!animations_.empty()) {
    char clock[64];
    std::snprintf(clock, sizeof clock, " %.2f/%.2f S %s", anim_time_, double(animations_[anim_].duration),
                  playing_ ? "PLAYING" : "PAUSED");
    // (Which one, when there is a choice.)
    const std::string which = animations_.size() > 1 ? " " + animation_label() : "";
    items.insert(items.end() - 1, "ANIMATION" + which + clock);
  }
  std::vector<std::string> lines(1);
  for (const std::string& item : items) {
    std::string joined = lines.back().empty() ? item : lines.back() + "  " + item;
    if (lines.back().empty() || text_width(joined, s) <= room) lines.back() = joined;
    else lines.push_back(ellipsize(item, room, s));
  }
  const int bar = (int(lines.size()) * 10 + 2) * s;
  d.rect(0, height_ - bar, width_, bar, {0, 0, 0, 140});
  for (size_t i = 0; i < lines.size(); ++i)
    d.text(3 * s, height_ - bar + (2 + 10 * int(i)) * s, lines[i], {220, 230, 255, 255}, s);
  // Messages (an error can be long: a path) wrap within the frame, above the bar.
  if (message_time_ > 0) {
    std::string m = wrap_text(message_, std::max(width_ - 16 * s, 1), s);
    int y = height_ - bar - 8 * s - text_height(m, s);
    size_t start = 0;
    while (start <= m.size()) {
      size_t end = std::min(m.find('\n', start), m.size());
      d.text_centered(width_ / 2, y, m.substr(start, end - start), {255, 230, 120, 255}, s);
      y += 10 * s;
      start = end + 1;
    }
  }
  if (help_) {
    const char* help =
        "LEFT DRAG: ROTATE   RIGHT DRAG: PAN   WHEEL: ZOOM\n"
        "SHIFT+LEFT DRAG: MOVE THE LIGHT   G: GRID   X: AXES\n"
        "ARROWS: ORBIT   + -: ZOOM   SPACE: SPIN   R: OPENING VIEW\n"
        "S: SHADING   W: WIREFRAME   P: PAINTER / Z-BUFFER\n"
        "A: SSAA 1-3   T: AFFINE / PERSPECTIVE   B: BACK FACES\n"
        "[ ]: POINT SIZE   K: PLAY / PAUSE   J L: STEP BACK / ON\n"
        "O: SHADOWS   N: NEXT ANIMATION\n"
        "C or F12: SCREENSHOT   SHIFT+F12: WITH THIS TEXT\n"
        "F2: SCREEN MODE   F3: FPS\n"
        "F11: FULLSCREEN   DROP A FILE TO OPEN IT   ESC: QUIT";
    std::string wrapped = wrap_text(help, std::max(width_ - 16 * s, 1), s);
    int w = text_width(wrapped, s) + 16 * s, h = text_height(wrapped, s) + 16 * s;
    int x = (width_ - w) / 2, y = (height_ - h) / 2;
    d.rect(x, y, w, h, {10, 20, 40, 200});
    d.text(x + 8 * s, y + 8 * s, wrapped, {255, 255, 255, 255}, s);
  }
}

}  // namespace velocity::realtime
