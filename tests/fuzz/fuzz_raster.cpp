// Fuzz target: the whole frame (transform, light, clip, set-up, bin, rasterize, shade,
// resolve) on hostile geometry. The input's bytes choose everything: the framebuffer
// (1x1 up to 2048 a side, super-sampling 1..4, at most 512 K samples), the camera (any
// position and angles, perspective or orthographic, odd near/far), lights, and up to
// four meshes whose coordinates, normals, uvs and colours are mostly small numbers but
// often NaN, +-Inf, 1e30, denormals or raw float bits, with vertices behind the eye,
// zero-area and sliver triangles; materials with every shading mode, textures,
// environment maps, filters and wrap modes; object hierarchies; painter's mode,
// culling, affine mapping, 1..3 threads.
//
// Properties: no sanitizer report (ASan sees any write outside the buffers), no
// exception other than velocity::Error, the framebuffer and both images keep the size
// that was asked for, and the renderer still works for the next frame.
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "fuzz_util.hpp"
#include "velocity/error.hpp"
#include "velocity/renderer.hpp"
#include "velocity/scene.hpp"
#include "velocity/texture.hpp"

namespace {

using namespace velocity;

// The input as a stream of choices; past its end every read returns 0.
class Bytes {
 public:
  Bytes(const uint8_t* data, size_t size) : p_(data), n_(size) {}
  uint8_t u8() {
    if (n_ == 0) return 0;
    --n_;
    return *p_++;
  }
  uint16_t u16() { return uint16_t(u8() | (u8() << 8)); }
  uint32_t u32() { return uint32_t(u16()) | (uint32_t(u16()) << 16); }
  bool flag() { return u8() & 1; }
  // True with probability about k / 256.
  bool chance(int k) { return u8() < k; }
  int below(int n) { return int(u8() % n); }

  // A float: mostly an ordinary one, often one a renderer finds hard.
  float number() {
    uint8_t k = u8();
    if (k < 176) return float(int8_t(u8())) / 32.0f;  // [-4, 4], the view's scale
    if (k < 216) return float(int16_t(u16())) / 64.0f;  // [-512, 512]
    if (k < 236) {
      static const float special[20] = {0.0f,
                                        -0.0f,
                                        1.0f,
                                        -1.0f,
                                        0.5f,
                                        std::numeric_limits<float>::quiet_NaN(),
                                        std::numeric_limits<float>::infinity(),
                                        -std::numeric_limits<float>::infinity(),
                                        1e30f,
                                        -1e30f,
                                        1e-30f,
                                        FLT_MAX,
                                        -FLT_MAX,
                                        std::numeric_limits<float>::denorm_min(),
                                        1e7f,
                                        -1e7f,
                                        16384.0f,
                                        8388608.0f,
                                        1e-7f,
                                        3.0f};
      return special[k - 216];
    }
    uint32_t bits = u32();  // anything at all
    float f;
    std::memcpy(&f, &bits, 4);
    return f;
  }
  // Mostly a small coordinate, sometimes anything.
  float coord() { return chance(232) ? float(int8_t(u8())) / 48.0f : number(); }
  Vec3 vec3() { return {number(), number(), number()}; }
  Vec3 coord3() { return {coord(), coord(), coord()}; }
  Vec3 color() { return chance(220) ? Vec3{u8() / 255.0f, u8() / 255.0f, u8() / 255.0f} : vec3(); }

 private:
  const uint8_t* p_;
  size_t n_;
};

// A few textures, made once: odd sizes, one texel, a long thin strip, a checkerboard.
std::shared_ptr<const Texture> texture(int which) {
  static const std::vector<std::shared_ptr<const Texture>> all = [] {
    std::vector<std::shared_ptr<const Texture>> v;
    v.push_back(std::make_shared<const Texture>(Image(1, 1, 0xff3366ccu)));
    Image odd(3, 5);
    for (size_t i = 0; i < odd.pixels.size(); ++i) odd.pixels[i] = uint8_t(i * 37);
    v.push_back(std::make_shared<const Texture>(odd));
    v.push_back(std::make_shared<const Texture>(Image(64, 1, 0xff00ff00u)));
    v.push_back(std::make_shared<const Texture>(make_checkerboard(32, 4)));
    v.push_back(std::make_shared<const Texture>(make_environment_map(16)));
    return v;
  }();
  return which < 0 ? nullptr : all[size_t(which) % all.size()];
}

std::shared_ptr<const Texture> maybe_texture(Bytes& in) { return in.chance(100) ? texture(in.below(5)) : nullptr; }

const Shading kShadings[] = {Shading::Flat,        Shading::Gouraud,   Shading::Phong,
                             Shading::Unlit, Shading::Wireframe, Shading::Points};
const Filter kFilters[] = {Filter::Nearest, Filter::Bilinear, Filter::Trilinear};

Material material(Bytes& in) {
  Material m;
  m.color = in.color();
  m.shading = kShadings[in.below(6)];
  if (in.flag()) m.specular = in.chance(200) ? in.u8() / 255.0f : in.number();
  if (in.flag()) m.shininess = in.chance(200) ? float(in.u8()) : in.number();
  m.two_sided = in.flag();
  m.texture = maybe_texture(in);
  m.texture_mode = in.flag() ? TextureMode::Modulate : TextureMode::Replace;
  m.env_map = maybe_texture(in);
  if (in.flag()) m.env_mix = in.chance(200) ? in.u8() / 255.0f : in.number();
  m.filter = kFilters[in.below(3)];
  m.wrap = in.flag() ? Wrap::Repeat : Wrap::Clamp;
  return m;
}

std::shared_ptr<Mesh> mesh(Bytes& in) {
  auto m = std::make_shared<Mesh>();
  m->name = "fuzz";
  const int nv = 1 + in.below(24);
  for (int i = 0; i < nv; ++i) m->positions.push_back(in.coord3());
  const int nt = in.below(40);
  for (int i = 0; i < nt; ++i) {
    Triangle t;
    for (uint32_t& v : t.v) v = uint32_t(in.below(nv));
    m->triangles.push_back(t);
  }
  // Optional attribute arrays, each exactly one entry per vertex / face (the API's
  // contract; validate() checks it).
  if (in.flag())
    for (int i = 0; i < nv; ++i) m->uvs.push_back({in.coord(), in.coord()});
  if (in.flag())
    for (int i = 0; i < nv; ++i) m->colors.push_back(in.color());
  if (in.chance(40))
    for (int i = 0; i < nt; ++i) m->face_colors.push_back(in.color());
  int materials = in.below(3);
  for (int i = 0; i < materials; ++i) m->materials.push_back(material(in));
  if (materials > 1)
    for (int i = 0; i < nt; ++i) m->face_materials.push_back(uint32_t(in.below(materials)));
  if (in.chance(60))
    for (int i = 0; i < nt; ++i) m->smoothing_groups.push_back(in.u8() & 7);
  switch (in.below(3)) {
    case 0: break;  // no normals: lit with face normals
    case 1: compute_normals(*m); break;
    case 2:
      for (int i = 0; i < nv; ++i) m->normals.push_back(in.vec3());
      break;
  }
  return m;
}

Camera camera(Bytes& in) {
  Camera c;
  if (in.flag()) {
    // Near the scene, looking at it or anywhere.
    c.position = {in.coord(), in.coord(), 1.0f + in.coord()};
    if (in.flag()) c.look_at({in.coord(), in.coord(), in.coord()});
  } else {
    c.position = in.vec3();
    c.yaw = in.number(), c.pitch = in.number(), c.roll = in.number();
  }
  if (in.chance(60)) c.projection = Projection::Orthographic;
  if (in.chance(24)) c.fov_y = in.number();
  if (in.chance(24)) c.ortho_height = in.number();
  if (in.chance(24)) c.near = in.number();
  if (in.chance(24)) c.far = in.number();
  return c;
}

std::vector<Light> lights(Bytes& in) {
  std::vector<Light> v;
  int n = in.below(4);
  for (int i = 0; i < n; ++i) {
    switch (in.below(3)) {
      case 0: v.push_back(Light::ambient(in.color())); break;
      case 1: v.push_back(Light::directional(in.vec3(), in.color())); break;
      case 2: {
        Light l = Light::point(in.coord3(), in.color(), in.flag() ? in.number() : 0, in.flag() ? in.number() : 0);
        if (in.flag()) l.constant = in.number();
        v.push_back(l);
        break;
      }
    }
  }
  return v;
}

Transform transform(Bytes& in) {
  Transform t;
  if (in.flag()) t.scale = in.chance(200) ? Vec3{1 + in.coord(), 1 + in.coord(), 1 + in.coord()} : in.vec3();
  if (in.flag()) t.rotation = in.chance(200) ? in.coord3() : in.vec3();
  if (in.flag()) t.translation = in.coord3();
  return t;
}

void check_frame(const Renderer& r, int w, int h, int ssaa) {
  fuzz_check(r.width() == w && r.height() == h);
  // Colour and depth of every sample, in whole 64x64 tiles (framebuffer.hpp), and on the
  // CPU a byte of stencil (the GPU's draws keep none).
  auto tiled = [](int n) { return size_t((n + 63) / 64 * 64); };
  const size_t per_sample = std::string(r.stats().backend) == "gpu" ? 8 : 9;
  fuzz_check(r.framebuffer_bytes() == tiled(w * ssaa) * tiled(h * ssaa) * per_sample);
  Image color = r.color_image(), depth = r.depth_image();
  fuzz::check_image(color);
  fuzz::check_image(depth);
  fuzz_check(color.width == w && color.height == h && depth.width == w && depth.height == h);
}

// A side of 1..64 mostly, up to 512 or 2048 now and then, and a super-sampling factor,
// within 512 K samples in all (2048x256, 1024x512, 512x512 at 1x1, ...) so that one
// input stays fast (a hundred full-screen Phong triangles at 1 M samples took 13 s under
// ASan); the unit tests (test_hostile.cpp) render 2048x2048 and up to 16384x16384.
constexpr int64_t kMaxSamples = int64_t(1) << 19;
void size(Bytes& in, int& w, int& h, int& ssaa) {
  uint8_t k = in.u8();
  int most = k < 240 ? 64 : k < 254 ? 512 : 2048;  // big frames are slow: rarely
  w = 1 + int(in.u16() % most), h = 1 + int(in.u16() % most);
  while (int64_t(w) * h > kMaxSamples) (w > h ? w : h) /= 2;
  ssaa = 1 + in.below(4);
  while (ssaa > 1 && int64_t(w) * h * ssaa * ssaa > kMaxSamples) --ssaa;
}

// VELOCITY_BACKEND=gpu replays the inputs on the GPU backend (tests/gpu).
BackendChoice backend() {
  const char* s = std::getenv("VELOCITY_BACKEND");
  return s && parse_backend(s) ? *parse_backend(s) : BackendChoice::Cpu;
}

void run(Bytes& in) {
  int w, h, ssaa;
  size(in, w, h, ssaa);
  static const BackendChoice choice = backend();
  Renderer r(w, h, choice);
  RenderOptions& o = r.options;
  o.depth_mode = in.chance(50) ? DepthMode::Painter : DepthMode::ZBuffer;
  o.cull_back_faces = in.flag();
  if (in.chance(100)) o.shading = kShadings[in.below(6)];
  if (in.chance(40)) o.texture = texture(in.below(5));
  if (in.chance(40)) o.env_map = texture(in.below(5));
  if (in.chance(60)) o.filter = kFilters[in.below(3)];
  o.affine = in.chance(40);
  o.ssaa = ssaa;
  o.threads = 1 + in.below(3);

  Scene scene;
  scene.camera = camera(in);
  scene.lights = lights(in);
  scene.background = in.color();
  const int objects = 1 + in.below(4);
  for (int i = 0; i < objects; ++i) {
    ObjectId parent = i > 0 && in.chance(60) ? ObjectId(in.below(i)) : kNoParent;
    ObjectId id = scene.add_object("o" + std::to_string(i), in.chance(20) ? nullptr : mesh(in), parent);
    Object& obj = scene.object(id);
    obj.transform = transform(in);
    obj.visible = !in.chance(20);
    if (in.chance(60)) obj.material = material(in);
  }
  if (in.chance(40)) scene.frame_camera(float(w) / float(h));

  // Frame 1: the whole scene. Frame 2 (sometimes): immediate mode, after a resize and a
  // change of super-sampling, with an override material.
  try {
    const FrameStats& st = r.render(scene);
    if (std::getenv("VELOCITY_FUZZ_VERBOSE"))
      std::fprintf(stderr,
                   "frame 1: %dx%d ssaa %d, %zu objects (%zu culled), %zu triangles (%zu rejected, %zu nonfinite, "
                   "%zu clipped, %zu culled), %zu rasterized, %zu lines, %zu points\n",
                   w, h, ssaa, st.objects, st.objects_culled, st.triangles, st.triangles_rejected,
                   st.triangles_nonfinite, st.triangles_clipped, st.triangles_culled, st.triangles_rasterized, st.lines,
                   st.points);
  } catch (const Error&) {
    return;
  }
  check_frame(r, w, h, ssaa);
  if (!in.flag()) return;

  int w2 = w, h2 = h, ssaa2 = ssaa;
  if (in.flag()) size(in, w2, h2, ssaa2);
  // resize() keeps the current factor until the next begin_frame: stay small meanwhile.
  if (int64_t(w2) * h2 * ssaa * ssaa > kMaxSamples) w2 = w, h2 = h;
  const bool bad_ssaa = in.chance(10);  // out of range: must throw and change nothing
  try {
    r.resize(w2, h2);
    o.ssaa = bad_ssaa ? (in.flag() ? 0 : 5) : ssaa2;
    Material override_material = material(in);
    r.begin_frame(camera(in), lights(in), in.color());
    fuzz_check(!bad_ssaa);
    std::vector<Mat4> world = scene.world_matrices();
    for (size_t i = 0; i < scene.objects().size(); ++i)
      if (const auto& m = scene.objects()[i].mesh) r.draw(*m, world[i], in.flag() ? &override_material : nullptr);
    // Sometimes the frame ends in end_frame_into (tiles copied out as drawn): it must
    // write what read_color reads afterwards. (The last bytes read: older inputs keep
    // their paths.)
    const int channels = in.flag() ? 4 : 3;
    std::vector<uint8_t> into;
    if (in.flag()) into.assign(size_t(w2) * size_t(h2) * size_t(channels), 0x5a);
    const FrameStats& st = into.empty() ? r.end_frame() : r.end_frame_into(into.data(), size_t(w2) * channels, channels);
    if (!into.empty()) {
      std::vector<uint8_t> again(into.size(), 0);
      r.read_color(again.data(), size_t(w2) * channels, channels);
      fuzz_check(again == into);
    }
    if (std::getenv("VELOCITY_FUZZ_VERBOSE"))
      std::fprintf(stderr, "frame 2: %dx%d ssaa %d, %zu triangles, %zu rasterized, %zu lines\n", w2, h2, ssaa2,
                   st.triangles, st.triangles_rasterized, st.lines);
  } catch (const Error&) {
    fuzz_check(bad_ssaa);
    check_frame(r, w2, h2, ssaa);  // the failed begin_frame changed nothing
    return;
  }
  check_frame(r, w2, h2, ssaa2);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Bytes in(data, size);
  run(in);
  return 0;
}
