// `velocity info`: what a model file holds.
#include <cstdio>

#include "commands.hpp"
#include "velocity/load.hpp"

namespace velocity::cli {

namespace {

const char* light_kind(LightType t) {
  switch (t) {
    case LightType::Ambient: return "ambient";
    case LightType::Directional: return "directional";
    case LightType::Point: return "point";
    case LightType::Spot: return "spot";
  }
  return "?";
}

int run_info(const std::string& path, bool swap_yz, size_t max_memory) {
  LoadOptions options;
  options.swap_yz = swap_yz;
  options.max_memory = max_memory;
  Model model = load_model(path, options);
  std::printf("file: %s\nobjects: %zu\nvertices: %zu\ntriangles: %zu\n", path.c_str(), model.nodes.size(),
              model.vertex_count(), model.triangle_count());
  bool any = false;
  Bounds all;
  for (const ModelNode& n : model.nodes) {
    if (!n.mesh) {
      std::printf("  %-24s (no mesh)\n", n.name.c_str());
      continue;
    }
    const Mesh& m = *n.mesh;
    std::printf("  %-24s %8zu vertices %8zu triangles %3zu materials%s\n", n.name.c_str(), m.vertex_count(),
                m.triangle_count(), m.materials.size(), m.uvs.empty() ? "" : ", uv");
    for (const Material& mat : m.materials) {
      std::printf("    material %-20s colour %.3f %.3f %.3f  %s%s\n", ('"' + mat.name + '"').c_str(), mat.color.x,
                  mat.color.y, mat.color.z, std::string(to_string(mat.shading)).c_str(),
                  mat.two_sided ? ", two-sided" : "");
      if (!mat.texture_file.empty())
        std::printf("      texture %s (%s)\n", mat.texture_file.c_str(),
                    mat.texture ? (std::to_string(mat.texture->width()) + "x" + std::to_string(mat.texture->height())).c_str()
                                : "not found");
    }
    if (m.positions.empty()) continue;
    Bounds b = m.bounds();
    if (!any) all = b, any = true;
    all.min = {std::min(all.min.x, b.min.x), std::min(all.min.y, b.min.y), std::min(all.min.z, b.min.z)};
    all.max = {std::max(all.max.x, b.max.x), std::max(all.max.y, b.max.y), std::max(all.max.z, b.max.z)};
  }
  for (const Light& l : model.lights)
    std::printf("light: %s colour %.3f %.3f %.3f\n", light_kind(l.type), l.color.x, l.color.y, l.color.z);
  for (const NamedCamera& c : model.cameras)
    std::printf("camera: %s at %.3f %.3f %.3f, fov %.1f degrees\n", c.name.c_str(), c.camera.position.x,
                c.camera.position.y, c.camera.position.z, c.camera.fov_y * 180.0 / 3.14159265358979);
  if (any)
    std::printf("bounds: min %.4g %.4g %.4g  max %.4g %.4g %.4g (object space)\n", all.min.x, all.min.y, all.min.z,
                all.max.x, all.max.y, all.max.z);
  return 0;
}

}  // namespace

std::function<int()> add_info_command(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  auto swap = std::make_shared<bool>(true);
  auto max_memory = std::make_shared<size_t>(LoadOptions{}.max_memory);
  CLI::App* cmd = app.add_subcommand("info", "Print the objects, counts, materials, lights, cameras and bounds of a model file");
  cmd->add_option("file", *path, "Model file")->required();
  cmd->add_flag("!--no-swap-yz", *swap, "Keep 3D Studio's Z-up coordinates (ASC files)");
  cmd->add_option("--max-memory", *max_memory, "Most the loader may allocate, e.g. 512M (K, M, G: x1024)")
      ->transform(CLI::AsSizeValue(false))
      ->check(CLI::Range(size_t(1), SIZE_MAX))
      ->capture_default_str();
  return [path, swap, max_memory] { return run_info(*path, *swap, *max_memory); };
}

}  // namespace velocity::cli
