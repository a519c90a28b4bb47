// `velocity render`: a model file, a generated model or the demo scene, to an image.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <sstream>

#include "commands.hpp"
#include "velocity/animation.hpp"
#include "velocity/demo.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"
#include "velocity/renderer.hpp"
#include "velocity/texture.hpp"
#include "velocity/view_setup.hpp"

namespace velocity::cli {

void parse_size(const std::string& text, int& width, int& height) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X'))
    throw CLI::ValidationError("--size", "expected WxH, e.g. 1280x720, got '" + text + "'");
  if (w < 1 || h < 1 || w > 16384 || h > 16384)
    throw CLI::ValidationError("--size", "width and height must be 1..16384, got '" + text + "'");
  width = w, height = h;
}

namespace {

struct RenderArgs {
  std::string model;  // empty: the demo scene
  std::string size = "1280x720";
  std::string shade;
  std::string camera;
  std::string out = "velocity.png";
  std::string depth_out;
  std::string texture, env, filter;
  float fov = 0;
  int ssaa = 0;  // 0: 3 for the demo scene, 1 for anything else
  float point_size = 1.0f;
  int threads = 0;
  std::optional<float> time;  // --time: pose an animated file at this second
  std::optional<size_t> animation;
  std::string backend = "cpu";
  bool ortho = false, painter = false, no_cull = false, cull = false, verbose = false, swap_yz = true, affine = false;
  size_t max_memory = LoadOptions{}.max_memory;
  AppearanceArgs appearance;
};

// --shade: a shading mode, optionally "+tex" and/or "+env" ("phong+env"); "tex" alone is
// Gouraud with a texture, "env" alone Phong with an environment map.
struct ShadeSpec {
  std::optional<Shading> shading;
  bool tex = false, env = false;
};

ShadeSpec parse_shade(const std::string& text) {
  ShadeSpec spec;
  std::stringstream ss(text);
  std::string part;
  bool first = true;
  while (std::getline(ss, part, '+')) {
    if (part == "tex") {
      spec.tex = true;
      if (first) spec.shading = Shading::Gouraud;
    } else if (part == "env") {
      spec.env = true;
      if (first) spec.shading = Shading::Phong;
    } else if (auto s = parse_shading(part); s && first) {
      spec.shading = s;
    } else {
      throw Error("--shade: unknown mode '" + text +
                  "' (flat, gouraud, phong, unlit, wire, points, pbr, tex, env, or a mode with +tex / +env)");
    }
    first = false;
  }
  if (first) throw Error("--shade: empty mode");
  return spec;
}

// "x,y,z" (looking at the scene's centre) or "x,y,z,yaw,pitch,roll" (degrees). Near and
// far are refitted around the scene from the new position.
void apply_camera(const std::string& text, Scene& scene) {
  std::vector<float> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      size_t used = 0;
      v.push_back(std::stof(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw Error("--camera: '" + item + "' is not a number (expected x,y,z[,yaw,pitch,roll])");
    }
  }
  if (v.size() != 3 && v.size() != 6) throw Error("--camera: expected x,y,z or x,y,z,yaw,pitch,roll, got '" + text + "'");
  Camera& camera = scene.camera;
  Sphere bounds = scene.bounds();
  camera.position = {v[0], v[1], v[2]};
  if (v.size() == 6)
    camera.yaw = radians(v[3]), camera.pitch = radians(v[4]), camera.roll = radians(v[5]);
  else
    camera.look_at(bounds.center);
  float d = length(bounds.center - camera.position), r = std::max(bounds.radius, 1e-3f);
  camera.near = std::max(d - r * 1.01f, std::max(d, r) * 1e-3f);
  camera.far = d + r * 1.01f;
}

bool scene_has_texture(const Scene& scene) {
  for (const Object& o : scene.objects()) {
    if (o.material && o.material->texture) return true;
    if (o.mesh)
      for (const Material& m : o.mesh->materials)
        if (m.texture) return true;
  }
  return false;
}

Scene build_scene(const RenderArgs& a, float aspect) {
  if (a.model.empty()) {
    if (a.time || a.animation) throw Error("--time and --animation pose an animated model file (glTF), not the demo scene");
    return make_demo_scene();
  }
  std::shared_ptr<Mesh> generated;
  if (a.model == "cube") generated = std::make_shared<Mesh>(make_cube(1.2f));
  else if (a.model == "sphere") generated = std::make_shared<Mesh>(make_sphere(48));
  else if (a.model == "torus") generated = std::make_shared<Mesh>(make_torus());
  if (!generated) {
    // As a model viewer shows it: back faces drawn and lit from both sides unless
    // --cull, the default light when the file brings none, a three-quarter view.
    LoadOptions options;
    options.swap_yz = a.swap_yz;
    options.max_memory = a.max_memory;
    if (!a.time && !a.animation) return scene_from_model(a.model, options, a.cull, aspect);
    // Framed at rest (as the viewer opens it), then posed: the camera does not follow the motion.
    std::vector<Animation> animations;
    std::vector<Skin> skins;
    Scene scene = scene_from_model(a.model, options, a.cull, aspect, &animations, &skins);
    try {
      pose_at(animations, a.animation.value_or(0), a.time.value_or(0.0f), skins, scene);
    } catch (const Error& e) {
      throw Error(a.model + ": " + e.what());
    }
    return scene;
  }
  if (a.time || a.animation) throw Error("--time and --animation pose an animated model file (glTF), not '" + a.model + "'");
  Scene scene;
  ObjectId id = scene.add_object(a.model, generated);
  scene.object(id).transform.rotation = {radians(20), radians(-30), 0};
  Material m;
  m.color = {0.8f, 0.7f, 0.6f};
  m.shading = Shading::Phong;
  m.specular = 0.5f;
  scene.object(id).material = m;
  scene.frame_camera(aspect, Vec3{0, 0, 1});
  return scene;
}

int run_render(const RenderArgs& a) {
  int w = 0, h = 0;
  parse_size(a.size, w, h);
  Scene scene = build_scene(a, float(w) / float(h));
  if (a.fov > 0) scene.camera.fov_y = radians(a.fov);
  if (a.ortho) scene.camera.projection = Projection::Orthographic;
  if (!a.camera.empty()) apply_camera(a.camera, scene);

  const std::optional<BackendChoice> backend = parse_backend(a.backend);
  if (!backend) throw Error("--backend: expected cpu|gpu|auto, got '" + a.backend + "'");
  Renderer renderer(w, h, *backend);
  RenderOptions& o = renderer.options;
  if (!a.shade.empty()) {
    ShadeSpec spec = parse_shade(a.shade);
    o.shading = spec.shading;
    // A mode asking for a texture uses --texture, else the model's own textures, else
    // the checkerboard; for an environment map --env, else the generated studio.
    if (spec.tex && a.texture.empty() && !scene_has_texture(scene))
      o.texture = std::make_shared<const Texture>(make_checkerboard());
    if (spec.env && a.env.empty()) o.env_map = std::make_shared<const Texture>(make_environment_map());
  }
  if (!a.texture.empty()) o.texture = load_texture(a.texture);
  if (!a.env.empty()) o.env_map = load_texture(a.env);
  if (!a.filter.empty()) {
    o.filter = parse_filter(a.filter);
    if (!o.filter) throw Error("--filter: expected nearest|bilinear|trilinear, got '" + a.filter + "'");
  }
  o.affine = a.affine;
  o.ssaa = a.ssaa ? a.ssaa : (a.model.empty() ? 3 : 1);
  if (o.ssaa < 1 || o.ssaa > 4) throw Error("--ssaa must be 1..4, got " + std::to_string(o.ssaa));
  if (!(a.point_size >= 1 && a.point_size <= 64))
    throw Error("--point-size must be 1..64, got " + std::to_string(a.point_size));
  o.point_size = a.point_size;
  if (a.threads < 0) throw Error("--threads must be 0 (every core) or more");
  o.threads = a.threads;
  o.depth_mode = a.painter ? DepthMode::Painter : DepthMode::ZBuffer;
  o.cull_back_faces = !a.no_cull;
  apply_appearance(a.appearance, o);
  const FrameStats& st = renderer.render(scene);
  write_image(a.out, renderer.color_image());
  // Never silently empty: say why nothing was drawn.
  const bool model_file = !a.model.empty() && a.model != "cube" && a.model != "sphere" && a.model != "torus";
  if (std::string why = explain_empty_frame(st, o.cull_back_faces && (a.cull || !model_file)); !why.empty())
    std::fprintf(stderr, "velocity: nothing was drawn: %s\n", why.c_str());
  if (!a.depth_out.empty()) write_image(a.depth_out, renderer.depth_image());
  if (a.verbose) {
    std::printf("backend=%s (%s)\n", st.backend, st.backend_reason);
    std::printf("size=%dx%d ssaa=%d samples=%dx%d framebuffer_bytes=%zu\n", w, h, o.ssaa, w * o.ssaa, h * o.ssaa,
                renderer.framebuffer_bytes());
    std::printf("objects=%zu culled=%zu triangles=%zu rejected=%zu clipped=%zu backface_or_empty=%zu nonfinite=%zu "
                "rasterized=%zu lines=%zu points=%zu\n",
                st.objects, st.objects_culled, st.triangles, st.triangles_rejected, st.triangles_clipped,
                st.triangles_culled, st.triangles_nonfinite, st.triangles_rasterized, st.lines, st.points);
    if (a.time || a.animation) std::printf("posed: animation %zu at %g s\n", a.animation.value_or(0), a.time.value_or(0.0f));
  }
  std::printf("wrote %s (%dx%d)%s%s\n", a.out.c_str(), w, h, a.depth_out.empty() ? "" : " and depth to ",
              a.depth_out.c_str());
  return 0;
}

}  // namespace

std::function<int()> add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a model file, a generated model or the demo scene");
  cmd->add_option("model", args->model,
                  "Model file (.asc, .plg, .obj, ...) or cube|sphere|torus; none: the demo scene");
  cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
  cmd->add_option("--shade", args->shade,
                  "Override shading: flat|gouraud|phong|unlit|wire|points|pbr|tex|env, or MODE+tex, MODE+env, MODE+tex+env");
  add_appearance_options(cmd, args->appearance);
  cmd->add_option("--texture", args->texture, "Base texture for every material (PNG, JPEG, TGA, BMP, GIF, PCX)");
  cmd->add_option("--env", args->env, "Sphere environment map for every material");
  cmd->add_option("--filter", args->filter, "Texture filter: nearest|bilinear|trilinear");
  cmd->add_flag("--affine", args->affine, "Affine (screen-linear) texture mapping: cheaper, bends on large polygons");
  cmd->add_option("--ssaa", args->ssaa, "Super-sampling factor per side, 1..4 (default: 3 for the demo scene, else 1)");
  cmd->add_option("--point-size", args->point_size, "Side of a point (points shading, point clouds) in pixels, 1..64")
      ->capture_default_str();
  cmd->add_option("--time", args->time,
                  "Pose an animated file (glTF) at this second of its animation (past its end: the last pose)");
  cmd->add_option("--animation", args->animation, "Which of the file's animations --time plays, from 0 (default 0)");
  cmd->add_option("--camera", args->camera, "Camera position x,y,z (looking at the model) or x,y,z,yaw,pitch,roll (degrees)");
  cmd->add_option("--fov", args->fov, "Vertical field of view in degrees");
  cmd->add_flag("--ortho", args->ortho, "Orthographic projection");
  cmd->add_flag("--painter", args->painter, "Painter's algorithm (depth sort) instead of the depth buffer");
  cmd->add_flag("--no-cull", args->no_cull, "Draw back faces of every material (model files draw theirs by default)");
  cmd->add_flag("--cull", args->cull, "Cull the back faces of a model file's one-sided faces (default: drawn, lit from both sides)");
  cmd->add_flag("!--no-swap-yz", args->swap_yz, "Keep 3D Studio's Z-up coordinates (ASC files)");
  cmd->add_option("--max-memory", args->max_memory, "Most the model loader may allocate, e.g. 512M (K, M, G: x1024)")
      ->transform(CLI::AsSizeValue(false))
      ->check(CLI::Range(size_t(1), SIZE_MAX))
      ->capture_default_str();
  cmd->add_option("--out", args->out, "Output image (.png or .ppm)")->capture_default_str();
  cmd->add_option("--depth", args->depth_out, "Also write the depth buffer as a greyscale image");
  cmd->add_option("--threads", args->threads, "Threads rasterizing tiles (0: every core)")->capture_default_str();
  cmd->add_option("--backend", args->backend, "What draws: cpu, gpu (OpenGL 3.3 through EGL) or auto (a hardware GPU, else cpu)")
      ->capture_default_str();
  cmd->add_flag("--verbose", args->verbose, "Print what the frame did");
  // With no subcommand at all, `velocity` runs this with its defaults.
  return [args] { return run_render(*args); };
}

}  // namespace velocity::cli
