// Velocity reference renderer: the benchmark scene drawn by Mesa's llvmpipe through
// OSMesa, as an independent yardstick for the engine's golden-image tests and
// benchmarks. Nothing here uses the engine's code: the meshes, the scene and the
// shading follow the written scene convention (docs: the reference tools README) and
// produce the same images as the `glref` tool for the same settings.
//
// Scene convention, in short: the mesh is centred on its bounding-box centre and
// scaled to a bounding sphere of radius 1; camera at (0,0,3) looking down -Z, vertical
// fov 45 degrees, near 0.1, far 100; frame i spins the mesh 360*i/frames degrees about
// +Y; one white directional light from normalise(0.3,0.5,1) in eye space, ambient 0.2,
// diffuse 0.8, material (0.8,0.7,0.6); CCW front faces, back faces culled, depth LESS,
// clear colour (0.1,0.1,0.15).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vref {

// Indexed triangle mesh; attributes are per vertex (xyz, xyz, uv).
struct Mesh {
  std::vector<float> pos, nrm, uv;
  std::vector<uint32_t> idx;

  size_t vertices() const { return pos.size() / 3; }
  size_t triangles() const { return idx.size() / 3; }
};

// UV sphere of `segs` segments and segs/2 rings (2*segs*(segs/2) triangles), unit
// radius, v = 1 at the north pole, u running with longitude. Throws
// std::invalid_argument unless 3 <= segs <= 16384.
Mesh make_sphere(int segs);

// Wavefront OBJ through tinyobjloader (polygons triangulated), with smooth normals:
// face normals summed over all corners sharing a position, then normalised.
// Throws std::runtime_error if the file cannot be read or holds no triangles.
Mesh load_obj(const std::string& path);

// "sphere:SEGS" -> make_sphere, anything else -> load_obj (the CLI's --mesh).
Mesh load_mesh(std::string_view spec);

// Centres the mesh on its bounding-box centre and scales it so the bounding sphere
// about that centre has radius 1. Normals are left alone (uniform scale).
void normalise(Mesh& mesh);

// Unshares the vertices so that each triangle carries its own face normal,
// normalise((v1-v0) x (v2-v0)); used for flat shading.
Mesh face_normals(const Mesh& mesh);

// Pbr and PbrTex: glTF 2.0's metallic-roughness BRDF per fragment (metallic 0.3,
// roughness 0.5; PbrTex with the texture as an sRGB base colour), lit in linear light and
// written sRGB-encoded: the engine's `bench --shade pbr|pbrtex` (see kPbrFragmentShader).
enum class Shade { Flat, Gouraud, Tex, Phong, Env, Wire, Pbr, PbrTex };

// "flat" | "gouraud" | "tex" | "phong" | "env" | "wire" | "pbr" | "pbrtex"; nullopt otherwise.
std::optional<Shade> parse_shade(std::string_view name);
std::string_view to_string(Shade shade);

// Whether the shade reads Scene::texture (tex, env, pbrtex).
bool textured(Shade shade);

// 8-bit RGBA image, top row first, 4 bytes per pixel.
struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;

  bool empty() const { return rgba.empty(); }
};

// The convention's default texture: 256x256, 32-texel squares, colours
// (40,60,160) at the origin square and (230,200,80).
Image checkerboard();

// Any format stb_image reads, converted to RGBA. Throws std::runtime_error.
Image load_image(const std::string& path);

struct Scene {
  std::string mesh = "sphere:64";  // as load_mesh()
  int width = 1920, height = 1080;
  Shade shade = Shade::Gouraud;
  int copies = 1;                  // mesh drawn this many times, in a ceil(sqrt(N)) grid
  Image texture;                   // for Tex, Env and PbrTex; empty -> checkerboard()
  // A shadow map for the light (the programmable modes: phong, env, pbr, pbrtex): a
  // depth texture of shadow_map_size texels a side drawn each frame from the light,
  // orthographic over the mesh's bounding sphere, read with a depth-compare sampler's
  // bilinear filter (percentage-closer) at the point moved two texels along its normal
  // and one towards the light: the engine's --shadows.
  bool shadows = false;
  int shadow_map_size = 2048;
};

// Owns an OSMesa (llvmpipe) context with its colour buffer, the prepared mesh and
// the GL state for one Scene. Each Renderer has its own context and makes it current
// on the calling thread when it draws, so several may coexist on one thread.
class Renderer {
 public:
  // Loads and prepares the mesh, creates the context and sets up the GL state.
  // Throws std::invalid_argument for a bad scene (size, copies, mesh spec) and
  // std::runtime_error for load, OSMesa or shader failures.
  explicit Renderer(const Scene& scene);
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Clears and draws frame `frame` of `frames` (rotation 360*frame/frames degrees
  // about +Y), the shadow map first when there is one, then glFinish, so the cost of
  // the frame is all inside this call.
  void draw_frame(int frame, int frames);

  // The last frame drawn, top row first.
  Image read_image() const;

  // Triangles submitted per frame, copies included.
  size_t triangles() const;

  // GL_RENDERER of the context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string gl_renderer() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace vref
