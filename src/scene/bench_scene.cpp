#include "velocity/bench_scene.hpp"

#include <cmath>

#include "velocity/error.hpp"
#include "velocity/load.hpp"

namespace velocity::bench {

namespace {

// All of a model's meshes as one, in model space (node matrices applied).
Mesh merge_model(const Model& model) {
  Mesh merged;
  std::vector<Mat4> world(model.nodes.size());
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    const ModelNode& n = model.nodes[i];
    world[i] = n.parent >= 0 ? world[size_t(n.parent)] * n.local : n.local;
    if (!n.mesh) continue;
    uint32_t base = uint32_t(merged.positions.size());
    for (Vec3 p : n.mesh->positions) merged.positions.push_back(world[i].transform_point(p));
    for (Triangle t : n.mesh->triangles) merged.triangles.push_back({{t.v[0] + base, t.v[1] + base, t.v[2] + base}});
  }
  return merged;
}

}  // namespace

Mesh make_mesh(const std::string& spec) {
  Mesh mesh;
  if (spec.rfind("sphere:", 0) == 0) {
    std::string n = spec.substr(7);
    size_t used = 0;
    int segs = 0;
    try {
      segs = std::stoi(n, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != n.size()) throw Error("mesh: expected sphere:SEGS, got '" + spec + "'");
    mesh = make_sphere(segs);
  } else {
    mesh = merge_model(load_model(spec));
    compute_normals(mesh);
  }
  if (mesh.triangles.empty()) throw Error("mesh: '" + spec + "' has no triangles");
  normalize_to_unit_sphere(mesh);
  mesh.touch();  // the benchmark never edits it: the GPU cache need not hash it (Mesh::revision)
  return mesh;
}

std::optional<Look> make_look(std::string_view shade, std::shared_ptr<const Texture> texture) {
  Look look;
  Material& m = look.material;
  m.color = {0.8f, 0.7f, 0.6f};
  auto textured = [&] { return texture ? texture : std::make_shared<const Texture>(make_checkerboard()); };
  if (shade == "flat") {
    m.shading = Shading::Flat;
  } else if (shade == "gouraud") {
    m.shading = Shading::Gouraud;
  } else if (shade == "phong") {
    m.shading = Shading::Phong, m.specular = 0.5f, m.shininess = 32.0f;
  } else if (shade == "wire") {
    m.shading = Shading::Wireframe, m.color = {0.9f, 0.9f, 0.9f};
    look.options.cull_back_faces = false;
  } else if (shade == "tex") {
    m.shading = Shading::Gouraud, m.color = {1, 1, 1};
    m.texture = textured(), m.filter = Filter::Trilinear;
  } else if (shade == "env") {
    m.shading = Shading::Phong, m.specular = 0.5f, m.shininess = 32.0f;
    m.env_map = textured(), m.env_mix = 1.0f, m.filter = Filter::Trilinear;
  } else if (shade == "pbr" || shade == "pbrtex") {
    // glTF's metallic-roughness, per pixel; "pbrtex" with a base colour texture (sRGB).
    m.shading = Shading::Pbr, m.pbr.metallic = 0.3f, m.pbr.roughness = 0.5f;
    if (shade == "pbrtex") {
      m.color = {1, 1, 1}, m.texture = textured(), m.filter = Filter::Trilinear;
    }
  } else {
    return std::nullopt;
  }
  return look;
}

void draw_frame(Renderer& renderer, const Mesh& mesh, const Material& material, int frame, int frames, int copies) {
  Camera camera;  // the defaults are the convention's
  renderer.begin_frame(camera, {}, {0.1f, 0.1f, 0.15f});
  Mat4 spin = rotate_y(radians(360.0f * float(frame) / float(std::max(frames, 1))));
  const int side = int(std::ceil(std::sqrt(double(std::max(copies, 1)))));
  for (int c = 0; c < copies; ++c) {
    Mat4 place = Mat4::identity();
    if (copies > 1) {
      float s = 2.0f / float(side);
      place = translate({-1 + s * (float(c % side) + 0.5f), -1 + s * (float(c / side) + 0.5f), 0}) *
              scale({s * 0.5f, s * 0.5f, s * 0.5f});
    }
    renderer.draw(mesh, place * spin, &material);
  }
  renderer.end_frame();
}

}  // namespace velocity::bench
