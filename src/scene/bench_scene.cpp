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
  return mesh;
}

Material make_material(Shading shading) {
  Material m;
  m.color = {0.8f, 0.7f, 0.6f};
  m.shading = shading;
  if (shading == Shading::Phong) m.specular = 0.5f, m.shininess = 32.0f;
  if (shading == Shading::Wireframe) m.color = {0.9f, 0.9f, 0.9f};
  return m;
}

RenderOptions make_options(Shading shading) {
  RenderOptions o;
  o.cull_back_faces = shading != Shading::Wireframe;
  return o;
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
