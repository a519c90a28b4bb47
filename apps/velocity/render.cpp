// `velocity render`: a model file, a generated model or the demo scene, to an image.
#include <cstdio>
#include <sstream>

#include "commands.hpp"
#include "velocity/demo.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"
#include "velocity/renderer.hpp"

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
  float fov = 0;
  bool ortho = false, painter = false, no_cull = false, verbose = false, swap_yz = true;
};

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

Scene build_scene(const RenderArgs& a, float aspect) {
  if (a.model.empty()) return make_demo_scene();
  Scene scene;
  std::shared_ptr<Mesh> generated;
  if (a.model == "cube") generated = std::make_shared<Mesh>(make_cube(1.2f));
  else if (a.model == "sphere") generated = std::make_shared<Mesh>(make_sphere(48));
  else if (a.model == "torus") generated = std::make_shared<Mesh>(make_torus());
  if (generated) {
    ObjectId id = scene.add_object(a.model, generated);
    scene.object(id).transform.rotation = {radians(20), radians(-30), 0};
    Material m;
    m.color = {0.8f, 0.7f, 0.6f};
    m.shading = Shading::Phong;
    m.specular = 0.5f;
    scene.object(id).material = m;
  } else {
    LoadOptions options;
    options.swap_yz = a.swap_yz;
    add_to_scene(scene, load_model(a.model, options));
  }
  scene.frame_camera(aspect);
  return scene;
}

int run_render(const RenderArgs& a) {
  int w = 0, h = 0;
  parse_size(a.size, w, h);
  Scene scene = build_scene(a, float(w) / float(h));
  if (a.fov > 0) scene.camera.fov_y = radians(a.fov);
  if (a.ortho) scene.camera.projection = Projection::Orthographic;
  if (!a.camera.empty()) apply_camera(a.camera, scene);

  Renderer renderer(w, h);
  if (!a.shade.empty()) {
    auto s = parse_shading(a.shade);
    if (!s) throw Error("--shade: unknown mode '" + a.shade + "' (flat, gouraud, phong, color, wire, points)");
    renderer.options.shading = s;
  }
  renderer.options.depth_mode = a.painter ? DepthMode::Painter : DepthMode::ZBuffer;
  renderer.options.cull_back_faces = !a.no_cull;
  const FrameStats& st = renderer.render(scene);
  write_image(a.out, renderer.color_image());
  if (!a.depth_out.empty()) write_image(a.depth_out, renderer.depth_image());
  if (a.verbose) {
    std::printf("objects=%zu culled=%zu triangles=%zu rejected=%zu clipped=%zu backface_or_empty=%zu nonfinite=%zu "
                "rasterized=%zu lines=%zu points=%zu\n",
                st.objects, st.objects_culled, st.triangles, st.triangles_rejected, st.triangles_clipped,
                st.triangles_culled, st.triangles_nonfinite, st.triangles_rasterized, st.lines, st.points);
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
  cmd->add_option("--shade", args->shade, "Override shading: flat|gouraud|phong|color|wire|points");
  cmd->add_option("--camera", args->camera, "Camera position x,y,z (looking at the model) or x,y,z,yaw,pitch,roll (degrees)");
  cmd->add_option("--fov", args->fov, "Vertical field of view in degrees");
  cmd->add_flag("--ortho", args->ortho, "Orthographic projection");
  cmd->add_flag("--painter", args->painter, "Painter's algorithm (depth sort) instead of the depth buffer");
  cmd->add_flag("--no-cull", args->no_cull, "Draw back faces too");
  cmd->add_flag("!--no-swap-yz", args->swap_yz, "Keep 3D Studio's Z-up coordinates (ASC files)");
  cmd->add_option("--out", args->out, "Output image (.png or .ppm)")->capture_default_str();
  cmd->add_option("--depth", args->depth_out, "Also write the depth buffer as a greyscale image");
  cmd->add_flag("--verbose", args->verbose, "Print what the frame did");
  // With no subcommand at all, `velocity` runs this with its defaults.
  return [args] { return run_render(*args); };
}

}  // namespace velocity::cli
