// The CPU backend (velocity/backend.hpp) and its frame, top to bottom. draw only
// records and plans a draw; end_frame runs the pipeline on every core:
//
//   shadow maps     with RenderOptions::shadows: each shadow-casting light's depth,
//                   drawn by this same pipeline from the light (shadows.hpp)
//   vertex stage    chunks of vertices: transform, project, snap, light   (all cores,
//                   geometry/, shading/)
//   triangle stage  chunks of triangles: reject, cull, clip, set up, bin  (all cores,
//                   triangle/; each worker into its own arena and tile lists)
//   (painter's mode: sort every record far to near, then bin: raster/bins)
//   tiles           clear, then each record in submission order: coverage, shading
//                   kernel, depth, colour                     (all cores, raster/)
//
// Jobs are numbered in submission order and tiles merge the workers' lists by job, so
// the image is the same for any number of threads.
//
// Streaming: a frame's first draws, while they are primitive batches and clears of
// moderate size, do not wait for end_frame. Each goes to the pool's workers as it is
// drawn (ThreadPool's stream): its vertices projected into arrays of its own, its
// triangle-stage jobs run and binned under their frame numbers, while the calling
// thread records the next draw (pGL's vertex work, which is serial). end_frame runs
// what is left of the stream with the calling thread too, then the other draws as
// above, numbered after the streamed ones: the bins, and so the image, are the same.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <deque>
#include <functional>
#include <mutex>
#include <new>

#include "core/srgb.hpp"
#include "core/thread_pool.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/read_back.hpp"
#include "framebuffer/resolve.hpp"
#include "geometry/normals.hpp"
#include "geometry/object_cull.hpp"
#include "geometry/tangents.hpp"
#include "geometry/vertex_stage.hpp"
#include "geometry/vertex_jobs.hpp"
#include "raster/bins.hpp"
#include "raster/rasterize.hpp"
#include "shading/lighting.hpp"
#include "shadows.hpp"
#include "simd/targets.hpp"
#include "triangle/stage.hpp"
#include "velocity/backend.hpp"
#include "velocity/error.hpp"

namespace velocity {

namespace {

using triangle::kTrianglesPerJob;

}  // namespace

// The CPU pipeline: records and plans the draws, then runs the stages on a thread pool.
class CpuBackend final : public Backend {
 public:
  CpuBackend(int width, int height) { resize(width, height, 1); }
  // A shadow map's depth pass: draws on `owner`'s threads.
  CpuBackend(int size, CpuBackend* owner) : owner_(owner) { resize(size, size, 1); }
  // The workers may be inside a stream's draws, which live here.
  ~CpuBackend() override { drop_stream(); }

  void resize(int w, int h) override { resize(w, h, ssaa); }
  int width() const override { return width_; }
  int height() const override { return height_; }
  void begin_frame(const Camera& camera, const std::vector<Light>& lights, const FrameStart& start,
                   const RenderOptions& options) override;
  void draw(const Mesh& mesh, const Mat4& world, const Material* material, uint32_t object_id) override;
  void draw(const PrimitiveBatch& batch, const PixelState& state, uint32_t primitives) override;
  void clear(const ClearRequest& request) override;
  const FrameStats& end_frame() override;
  const FrameStats& end_frame_into(uint8_t* rgba, size_t row_bytes, int channels) override;
  const FrameStats& stats() const override { return stats_; }

  Image color_image() const override {
    if (!resolved_valid_) return resolve_color(framebuffer, ssaa);
    Image out(width_, height_);
    std::memcpy(out.pixels.data(), resolved_.data(), resolved_.size() * sizeof(uint32_t));
    return out;
  }
  Image depth_image() const override { return resolve_depth(framebuffer, ssaa); }
  void read_color(uint8_t* rgba, size_t row_bytes, int channels) const override {
    if (resolved_valid_)
      velocity::read_color(resolved_.data(), width_, height_, size_t(width_), pool.get(), rgba, row_bytes, channels);
    else
      velocity::read_color(framebuffer, ssaa, pool.get(), rgba, row_bytes, channels);
  }
  void read_view_depth(float* out) const override {
    velocity::read_view_depth(framebuffer, ssaa, pool.get(), projection, out);
  }
  void read_window_depth(float* out) const override { velocity::read_window_depth(framebuffer, ssaa, pool.get(), out); }
  void read_stencil(uint8_t* out) const override { velocity::read_stencil(framebuffer, ssaa, out); }
  std::vector<uint32_t> object_ids() const override { return resolve_object_ids(framebuffer, ssaa); }
  size_t framebuffer_bytes() const override {
    return framebuffer.color.size() * sizeof(uint32_t) + framebuffer.depth.size() * sizeof(float) +
           framebuffer.stencil.size() + framebuffer.ids.size() * sizeof(uint32_t);
  }

 private:
  int width_ = 0, height_ = 0;  // the output size
  int ssaa = 1;                 // samples per output pixel, per side
  Framebuffer framebuffer;      // the samples: width * ssaa x height * ssaa
  // With super-sampling, the output image, resolved by the tile workers as they finish
  // each tile (run_frame); valid from the end of a frame until the next resize or frame.
  std::vector<uint32_t> resolved_;
  bool resolved_valid_ = false;
  raster::Bins bins;
  std::unique_ptr<ThreadPool> pool;

  // The frame being recorded.
  geometry::DrawList plan;
  std::vector<raster::DrawState> draw_states;
  std::vector<triangle::Job> jobs;
  std::deque<std::vector<Vec3>> averaged_normals;  // for meshes that bring none, reused (stable addresses)
  size_t averaged_used = 0;
  std::deque<std::vector<Vec4>> generated_tangents;  // for normal-mapped meshes that bring none, likewise
  size_t tangents_used = 0;
  bool orthographic = false;
  Material default_material;
  Mat4 view, projection, view_projection;
  FrameStart start;
  FrameStats stats_;

  geometry::VertexStage vertex_stage;      // its chunks, reused across frames
  triangle::TriangleStage triangle_stage;  // its workers' scratch, reused across frames

  // The stream (see the top of this file): the draws handed to the workers before
  // end_frame, in order, each with its own copy of its plan and its vertex outputs
  // (kept across frames, like the arrays of the vertex stage).
  struct Streamed {
    triangle::Job::Kind kind = triangle::Job::Kind::Batch;
    geometry::BatchDrawPlan batch;
    geometry::ClearPlan clear{};
    uint32_t primitives = 0;
    uint32_t first_job = 0;  // its first job's number in the frame
    std::vector<geometry::ProjectedVertex> projected;
    std::vector<uint32_t> codes;
  };
  // A batch of more primitives than this is drawn at end_frame, on every core (one
  // streamed draw runs on one worker), and so is everything after it.
  static constexpr uint32_t kMaxStreamedPrimitives = 4 * kTrianglesPerJob;
  std::deque<Streamed> streamed_;
  size_t streamed_used_ = 0;
  std::mutex streamed_mutex_;      // the deque's index (which moves as it grows), between caller and workers
  uint32_t streamed_jobs_ = 0;     // the jobs numbered before jobs[0]
  bool stream_open_ = false;       // the pool runs this frame's stream
  bool may_stream_ = false;        // the frame may still hand draws to the stream
  bool stage_started_ = false;     // the triangle stage's start() was called for this frame
  const std::function<void(int, int)> stream_job_ = [this](int item, int worker) { run_streamed(item, worker); };

  // Shadows (RenderOptions::shadows): the frame's lights and mesh draws, which all cast;
  // the lights given a map and one depth pass per map (reused across frames).
  struct Caster {
    const Mesh* mesh;
    Mat4 world;
    bool two_sided;  // drawn with a two-sided material: both faces cast
    const Material* material;  // the draw's own material (null: the mesh's)
    bool cut_out;              // a MASK or BLEND material: cast where its alpha passes
  };
  bool shadows_ = false;
  std::vector<Light> frame_lights_;
  std::vector<Caster> casters_;
  Sphere caster_bounds_{{}, -1};
  std::vector<ShadowLight> shadow_lights_;
  std::vector<std::unique_ptr<CpuBackend>> shadow_passes_;
  // What the depth passes last drew (render_shadows): while a frame's is the same, the
  // maps are kept, not drawn again. Cut-out casters are never compared (their textures
  // and alpha could change unseen): a frame with one draws its maps.
  struct ShadowKey {
    struct Cast {
      const Mesh* mesh;
      Mat4 world;
      bool two_sided;
      uint64_t geometry;  // geometry_fingerprint of the mesh
      bool operator==(const Cast&) const = default;
    };
    std::vector<Cast> casters;
    std::vector<ShadowView> views;
    int size = 0;
    bool cull_back_faces = true, reusable = false;
    bool same_as(const ShadowKey& k) const;
  };
  ShadowKey shadow_key_, next_shadow_key_;
  CpuBackend* owner_ = nullptr;  // a depth pass: its owner's frame and threads
  // A depth pass: the map it draws (16-bit codes, shading/shadow.hpp; its framebuffer
  // keeps no colour or depth) and the map's projection.
  BlockVector<uint16_t> shadow_codes_;
  const shading::ShadowMap* shadow_map_ = nullptr;
  // Texel (-1, -1) of the map in shadow_codes_ (shading/shadow.hpp's layout).
  uint16_t* shadow_texels() { return shadow_codes_.data() + shading::kShadowLead; }
  Material depth_material_, depth_two_sided_;

  ThreadPool& pool_for(int threads) {
    if (owner_) {
      ThreadPool& p = *owner_->pool;
      if (bins.workers() != p.size() || bins.tiles_x() != framebuffer.tiles_x || bins.tiles_y() != framebuffer.tiles_y)
        bins.resize(framebuffer.width, framebuffer.height, p.size());
      return p;
    }
    if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::min(threads, 256);
    // A pool made before this process was forked has no workers here: a new one.
    if (!pool || pool->size() != threads || pool->orphaned()) pool = std::make_unique<ThreadPool>(threads);
    if (bins.workers() != threads || bins.tiles_x() != framebuffer.tiles_x || bins.tiles_y() != framebuffer.tiles_y)
      bins.resize(framebuffer.width, framebuffer.height, threads);
    return *pool;
  }

  // Sizes the sample buffers for an output size and super-sampling factor. Throws
  // velocity::Error (and changes nothing) when either is out of range.
  void resize(int w, int h, int k) {
    if (k < 1 || k > 4) throw Error("super-sampling factor " + std::to_string(k) + " is out of range (1..4)");
    if (w < 1 || h < 1 || w > kMaxFramebufferSide || h > kMaxFramebufferSide)
      throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range (1.." +
                  std::to_string(kMaxFramebufferSide) + " a side)");
    if (int64_t(w) * k > kMaxFramebufferSide || int64_t(h) * k > kMaxFramebufferSide)
      throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " with " + std::to_string(k) + "x" +
                  std::to_string(k) + " super-sampling needs a sample buffer over " +
                  std::to_string(kMaxFramebufferSide) + " a side");
    if (w == width_ && h == height_ && k == ssaa && framebuffer.width == w * k) return;
    drop_stream();  // (a frame never ended: its workers use the bins)
    // Bins first, then the framebuffer, which reuses its buffers when they are large
    // enough (a program switching sizes or super-sampling factors allocates nothing)
    // and otherwise allocates new ones before it lets go of the old: when memory runs
    // out (velocity::Error) the renderer keeps its old size and buffers. Bins sized for
    // another framebuffer are sized again by pool_for before they are used.
    try {
      bins.resize(w * k, h * k, std::max(bins.workers(), 1));
    } catch (const std::bad_alloc&) {
      throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + ": out of memory for the tile bins");
    }
    resolved_valid_ = false;
    framebuffer.resize(w * k, h * k);
    width_ = w, height_ = h, ssaa = k;
  }

  void begin(const Mat4& view, const Mat4& projection, bool orthographic, const std::vector<Light>& lights,
             const FrameStart& start, const RenderOptions& options);
  // Where end_frame_into wants the colour: each tile copied there once drawn.
  struct ColorOut {
    uint8_t* rgba;
    size_t row_bytes;
    int channels;
  };
  const FrameStats& run_frame(bool painter, const ColorOut* out = nullptr);
  // The stream: a draw handed to it (false: not streamed; the draw goes to jobs), a
  // streamed draw run by a worker, and the stream's end.
  bool stream(const geometry::BatchDrawPlan* batch, const geometry::ClearPlan* clear, uint32_t primitives);
  void run_streamed(int item, int worker);
  void close_stream();
  void drop_stream() noexcept;
  void order_blended_draws();
  void render_shadows();
};

const char* simd_target() { return raster::simd_target(); }

std::unique_ptr<Backend> make_cpu_backend(int width, int height) {
  // VELOCITY_SIMD_TARGET, when set, names the kernels' instruction set (for tests).
  if (const std::string& error = simd::apply_target_request(); !error.empty()) throw Error(error);
  return std::make_unique<CpuBackend>(width, height);
}

void CpuBackend::begin_frame(const Camera& camera, const std::vector<Light>& lights, const FrameStart& start,
                             const RenderOptions& options) {
  if (options.shadows && (options.shadow_map_size < 16 || options.shadow_map_size > 8192))
    throw Error("shadow map size " + std::to_string(options.shadow_map_size) + " is out of range (16..8192)");
  resize(width_, height_, options.ssaa);  // follows a change of options.ssaa
  const int w = framebuffer.width, h = framebuffer.height;
  begin(camera.view(), camera.projection_matrix(float(w) / float(h)), camera.projection == Projection::Orthographic,
        lights, start, options);
  shadows_ = options.shadows;
  casters_.clear();
  caster_bounds_ = {{}, -1};
  if (shadows_) frame_lights_ = lights;
  // No lights: kDefaultLight's directional light (given in eye space) casts.
  if (shadows_ && lights.empty()) {
    const Mat4 v = camera.view();
    const Vec3 t = normalize(kDefaultLight.towards);
    frame_lights_ = {Light::directional({v.m[0][0] * t.x + v.m[1][0] * t.y + v.m[2][0] * t.z,
                                         v.m[0][1] * t.x + v.m[1][1] * t.y + v.m[2][1] * t.z,
                                         v.m[0][2] * t.x + v.m[1][2] * t.y + v.m[2][2] * t.z},
                                        kDefaultLight.diffuse)};
  }
}

void CpuBackend::begin(const Mat4& view, const Mat4& projection, bool orthographic, const std::vector<Light>& lights,
                       const FrameStart& start, const RenderOptions& options) {
  CpuBackend& r = *this;
  drop_stream();  // a frame begun again before it ended
  r.streamed_used_ = 0, r.streamed_jobs_ = 0;
  r.stage_started_ = false;
  // Shadow passes and painter's mode (its records are sorted at the end) do not stream.
  r.may_stream_ = !r.owner_ && options.depth_mode != DepthMode::Painter;
  r.framebuffer.keep_ids(options.object_ids);
  const int w = r.framebuffer.width, h = r.framebuffer.height;
  geometry::DrawList& p = r.plan;
  p.width = w, p.height = h;
  r.view = view;
  r.projection = projection;
  r.view_projection = r.projection * view;
  p.viewport = geometry::viewport_map(0, 0, w, h, 0.0f, 1.0f);
  p.guard = p.viewport.guard;
  shading::eye_lights(view, lights, p.lights);
  p.options = options;
  p.mesh_setup = {};
  p.mesh_setup.x1 = p.mesh_setup.px1 = w - 1;
  p.mesh_setup.y1 = p.mesh_setup.py1 = h - 1;
  p.mesh_setup.affine = options.affine;
  p.meshes.clear(), p.batches.clear(), p.clears.clear(), p.slots.clear();
  r.draw_states.clear();
  r.jobs.clear();
  r.averaged_used = 0;
  r.tangents_used = 0;
  r.orthographic = orthographic;
  r.start = start;
  r.stats_ = {};
}

namespace {

// A fingerprint of what a depth pass reads of a mesh, its positions and triangles, so
// that a mesh changed in place between frames has its maps drawn again. Four
// multiply-xor chains over the 32-bit words, so that the multiplies overlap.
uint64_t geometry_fingerprint(const Mesh& mesh) {
  uint64_t h[4] = {0x9e3779b97f4a7c15u, 0xbf58476d1ce4e5b9u, 0x94d049bb133111ebu, 0x2545f4914f6cdd1du};
  auto mix = [&](const void* data, size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    size_t i = 0;
    for (; i + 16 <= bytes; i += 16)
      for (int k = 0; k < 4; ++k) {
        uint32_t w;
        std::memcpy(&w, b + i + 4 * k, 4);
        h[k] = (h[k] ^ w) * 0x100000001b3u;
      }
    for (; i + 4 <= bytes; i += 4) {
      uint32_t w;
      std::memcpy(&w, b + i, 4);
      h[0] = (h[0] ^ w) * 0x100000001b3u;
    }
    h[1] = (h[1] ^ bytes) * 0x100000001b3u;
  };
  mix(mesh.positions.data(), mesh.positions.size() * sizeof(Vec3));
  mix(mesh.triangles.data(), mesh.triangles.size() * sizeof(Triangle));
  return h[0] ^ (h[1] << 1 | h[1] >> 63) ^ (h[2] << 2 | h[2] >> 62) ^ (h[3] << 3 | h[3] >> 61);
}

// Whether a draw of `mesh` with `material` (null: the mesh's own) has a slot whose
// alpha decides which pixels it covers: a Pbr material (as the frame shades it) that is
// MASK or BLEND. Such a draw casts through the Pbr kernel's alpha test.
bool casts_cut_out(const Mesh& mesh, const Material* material, const RenderOptions& o) {
  auto cut = [&](const Material& m) {
    return m.alpha_mode != AlphaMode::Opaque && o.shading.value_or(m.shading) == Shading::Pbr;
  };
  if (material) return cut(*material);
  return std::any_of(mesh.materials.begin(), mesh.materials.end(), cut);
}

}  // namespace

void CpuBackend::draw(const Mesh& mesh, const Mat4& world, const Material* material, uint32_t object_id) try {
  CpuBackend& r = *this;
  r.stats_.objects++;
  if (mesh.triangles.empty()) return;
  // Every mesh draw casts, seen or not.
  if (r.shadows_) {
    bool two_sided = material ? material->two_sided : mesh.materials.empty() && r.default_material.two_sided;
    if (!material)
      for (const Material& m : mesh.materials) two_sided = two_sided || m.two_sided;
    r.casters_.push_back({&mesh, world, two_sided || !r.plan.options.cull_back_faces, material,
                          casts_cut_out(mesh, material, r.plan.options)});
    r.caster_bounds_ = merge_bounds(r.caster_bounds_, world_bounds(mesh, world));
  }
  if (geometry::ViewVolume(r.view_projection).outside(mesh, world)) return void(r.stats_.objects_culled++);
  geometry::DrawList& p = r.plan;
  geometry::MeshDrawPlan d;
  d.mesh = &mesh;
  d.override_material = material;
  d.object_id = object_id;
  d.model_view = r.view * world;
  d.mvp = r.projection * d.model_view;
  d.normal_matrix = normal_matrix(d.model_view);
  // A depth pass draws cut-out casters with their own materials (render_shadows).
  const bool depth_only = r.owner_ && !casts_cut_out(mesh, material, r.plan.options);
  if (!mesh.normals.empty() || depth_only) {  // (a depth-only draw reads no normals)
    d.normals = &mesh.normals;
  } else {
    if (r.averaged_used == r.averaged_normals.size()) r.averaged_normals.emplace_back();
    std::vector<Vec3>& n = r.averaged_normals[r.averaged_used++];
    geometry::average_normals(mesh, n);
    d.normals = &n;  // normalised when transformed to eye space
  }
  geometry::plan_mesh_draw(p, r.draw_states, d, material, r.default_material);
  if (r.owner_) {
    // A depth pass: the flat kernel, no varyings, nothing computed per vertex but the
    // position (its colour goes nowhere: TileInputs::depth_only). A cut-out caster's
    // MASK and BLEND slots keep the Pbr kernel, whose alpha test drops the pixels
    // under the cut-off before they write depth; BLEND casts as MASK at 0.5
    // (docs/appearance.md, "Shadows").
    for (uint32_t i = 0; i < d.slot_count; ++i) {
      geometry::SlotPlan& s = p.slots[d.slot_begin + i];
      if (!depth_only && s.shading == Shading::Pbr && s.material->alpha_mode != AlphaMode::Opaque) {
        raster::PbrState& pbr = r.draw_states[s.draw_state].pbr;
        if (pbr.alpha_mode == AlphaMode::Blend) pbr.alpha_mode = AlphaMode::Mask, pbr.alpha_cutoff = 0.5f;
        s.blend = false;
        continue;
      }
      s.kernel = uint8_t(raster::KernelId::Flat), s.num_varyings = 0, s.flat = false, s.lit = false;
      s.vertex_color = false, s.uv_from_env = false;
    }
    d.blend = false;
    if (depth_only) d.light = d.normal = d.eye = d.vertex_color = d.vertex_specular_terms = false;
  }
  if (d.needs_tangents) {
    if (mesh.tangents.size() == mesh.positions.size() && !mesh.tangents.empty()) {
      d.tangents = &mesh.tangents;
    } else {
      if (r.tangents_used == r.generated_tangents.size()) r.generated_tangents.emplace_back();
      std::vector<Vec4>& t = r.generated_tangents[r.tangents_used++];
      int uv_set = 0;
      for (uint32_t i = 0; i < d.slot_count; ++i)
        if (p.slots[d.slot_begin + i].pbr_tangents) uv_set = p.slots[d.slot_begin + i].uv_set;
      const std::vector<Vec2>& uvs = uv_set == 1 && !mesh.uvs1.empty() ? mesh.uvs1 : mesh.uvs;
      geometry::generate_tangents(mesh, *d.normals, uvs.empty() ? std::vector<Vec2>(mesh.positions.size()) : uvs, t);
      d.tangents = &t;
    }
  }
  if (d.blend) d.centre = d.model_view.transform_point(mesh.bounding_sphere().center);
  const uint32_t index = uint32_t(p.meshes.size());
  p.meshes.push_back(d);
  const size_t nt = mesh.triangles.size();
  for (size_t b = 0; b < nt; b += kTrianglesPerJob)
    r.jobs.push_back({triangle::Job::Kind::Mesh, index, uint32_t(b), uint32_t(std::min(b + kTrianglesPerJob, nt))});
} catch (const std::bad_alloc&) {
  throw Error("Renderer::draw: out of memory recording mesh '" + mesh.name + "'");
}

void CpuBackend::draw(const PrimitiveBatch& batch, const PixelState& state, uint32_t primitives) try {
  CpuBackend& r = *this;
  r.stats_.objects++;
  if (primitives == 0) return;
  geometry::DrawList& p = r.plan;
  const geometry::BatchDrawPlan d = geometry::plan_batch_draw(p, r.draw_states, batch, state, primitives);
  if (r.stream(&d, nullptr, primitives)) return;
  const uint32_t index = uint32_t(p.batches.size());
  p.batches.push_back(d);
  for (uint32_t b = 0; b < primitives; b += kTrianglesPerJob)
    r.jobs.push_back({triangle::Job::Kind::Batch, index, b, std::min(b + kTrianglesPerJob, primitives)});
} catch (const std::bad_alloc&) {
  throw Error("Renderer::draw: out of memory recording a primitive batch");
}

void CpuBackend::clear(const ClearRequest& request) {
  CpuBackend& r = *this;
  geometry::ClearPlan c{request, 0, 0, r.plan.width - 1, r.plan.height - 1};
  if (request.scissor) {
    c.x0 = std::max(c.x0, request.x0), c.y0 = std::max(c.y0, request.y0);
    c.x1 = std::min(c.x1, request.x1 - 1), c.y1 = std::min(c.y1, request.y1 - 1);
  }
  if (r.stream(nullptr, &c, 1)) return;
  const uint32_t index = uint32_t(r.plan.clears.size());
  r.plan.clears.push_back(c);
  r.jobs.push_back({triangle::Job::Kind::Clear, index, 0, 1});
}

const FrameStats& CpuBackend::end_frame() {
  try {
    return run_frame(plan.options.depth_mode == DepthMode::Painter);
  } catch (const std::bad_alloc&) {
    throw Error("Renderer::end_frame: out of memory");
  }
}

const FrameStats& CpuBackend::end_frame_into(uint8_t* rgba, size_t row_bytes, int channels) {
  // Tiles hold output pixels only without super-sampling (else read_color resolves them).
  if (ssaa != 1) {
    end_frame();
    read_color(rgba, row_bytes, channels);
    return stats_;
  }
  const ColorOut out{rgba, row_bytes, channels};
  try {
    return run_frame(plan.options.depth_mode == DepthMode::Painter, &out);
  } catch (const std::bad_alloc&) {
    throw Error("Renderer::end_frame: out of memory");
  }
}

const FrameStats& CpuBackend::run_frame(bool painter, const ColorOut* out) {
  CpuBackend& r = *this;
  // The streamed draws first (they come before any other job), and before pool_for,
  // which may make a new pool.
  r.close_stream();
  ThreadPool& pool = r.pool_for(r.plan.options.threads);

  using Clock = std::chrono::steady_clock;
  auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  const Clock::time_point ts = Clock::now();
  if (r.shadows_ && !r.casters_.empty()) r.render_shadows();
  const Clock::time_point t0 = Clock::now();
  geometry::finish_color_plan(r.plan, r.draw_states);
  r.order_blended_draws();
  r.vertex_stage.run(pool, r.plan);
  const Clock::time_point t1 = Clock::now();
  if (!r.stage_started_) r.triangle_stage.start(r.bins, pool.size(), painter);
  r.stage_started_ = false;
  r.triangle_stage.run(pool, r.bins, r.plan, r.jobs, r.streamed_jobs_, r.framebuffer.width, r.framebuffer.height);
  if (painter) r.bins.bin_deferred();
  const Clock::time_point t2 = Clock::now();

  raster::TileInputs tiles;
  tiles.bins = &r.bins;
  tiles.draws = &r.draw_states;
  tiles.lights = &r.plan.lights;
  tiles.orthographic = r.orthographic;
  if (r.plan.linear) {
    const RenderOptions& o = r.plan.options;
    tiles.output = {true, std::isfinite(o.exposure) && o.exposure >= 0 ? o.exposure : 1.0f, o.tone_map};
  }
  tiles.depth_test = !painter;
  tiles.depth_only = r.owner_ != nullptr;
  if (r.owner_) {
    tiles.shadow_codes = r.shadow_texels(), tiles.shadow_size = r.framebuffer.width;
    tiles.shadow_perspective = r.shadow_map_->perspective;
    tiles.shadow_near = r.shadow_map_->near, tiles.shadow_far = r.shadow_map_->far;
  }
  tiles.clear_color_buffer = r.start.clear_color_buffer, tiles.clear_depth_buffer = r.start.clear_depth_buffer;
  tiles.color = raster::pack_rgba(r.start.color.x, r.start.color.y, r.start.color.z, r.start.color.w);
  tiles.depth = std::clamp(r.start.depth, 0.0f, 1.0f);
  tiles.clear_stencil_buffer = r.start.clear_stencil_buffer, tiles.stencil = r.start.stencil;
  r.framebuffer.expect_clear(tiles.color, tiles.depth, tiles.clear_stencil_buffer ? tiles.stencil : r.framebuffer.clean_stencil);
  // With super-sampling, each tile's output pixels are resolved by its worker as soon as
  // it is drawn, from samples still in the core's cache (a pass after the tiles, reading
  // 9x the output's bytes back from memory, was a fifth of drive --hq's frame). A tile
  // left as it was keeps the pixels the last frame resolved, unless there are none; the
  // pixels whose samples straddle two tiles come after.
  const bool resolve = r.ssaa > 1 && !r.owner_;
  const bool every_tile = !r.resolved_valid_;
  r.resolved_valid_ = false;
  if (resolve) r.resolved_.resize(size_t(r.width_) * size_t(r.height_));
  pool.run(r.bins.tile_count(), [&](int tile) {
    const bool drawn = raster::rasterize_tile(tiles, tile, r.framebuffer);
    if (out) r.framebuffer.read_color_tile(tile, out->rgba, out->row_bytes, out->channels);
    if (resolve && (drawn || every_tile))
      resolve_tile_color(r.framebuffer, r.ssaa, tile, r.resolved_.data(), size_t(r.width_));
  });
  if (resolve) {
    pool.run(resolve_seam_count(r.framebuffer, r.ssaa),
             [&](int line) { resolve_seam(r.framebuffer, r.ssaa, line, r.resolved_.data(), size_t(r.width_)); });
    r.resolved_valid_ = true;
  }
  const Clock::time_point t3 = Clock::now();
  r.stats_.vertex_ms = ms(t0, t1), r.stats_.triangle_ms = ms(t1, t2), r.stats_.tile_ms = ms(t2, t3);
  r.stats_.shadow_ms = ms(ts, t0);

  // The frame's statistics, and a warning for each mesh that lost triangles to NaN (once:
  // not again by a depth pass).
  r.triangle_stage.add_stats(r.stats_);
  if (!r.owner_) r.triangle_stage.warn_nonfinite(r.plan, r.jobs);
  return r.stats_;
}

bool CpuBackend::stream(const geometry::BatchDrawPlan* batch, const geometry::ClearPlan* clear, uint32_t primitives) {
  CpuBackend& r = *this;
  // Only a prefix of the frame's jobs streams: once a draw went to jobs, all do.
  if (!r.may_stream_ || !r.jobs.empty() || primitives > kMaxStreamedPrimitives) return r.may_stream_ = false;
  if (!r.stream_open_) {
    ThreadPool& pool = r.pool_for(r.plan.options.threads);
    if (pool.size() < 2) return r.may_stream_ = false;  // nothing to overlap with
    r.triangle_stage.start(r.bins, pool.size(), false);
    r.stage_started_ = true;
    pool.open_stream(r.stream_job_);
    r.stream_open_ = true;
  }
  Streamed* s;
  {
    std::lock_guard lock(r.streamed_mutex_);
    if (r.streamed_used_ == r.streamed_.size()) r.streamed_.emplace_back();
    s = &r.streamed_[r.streamed_used_];
  }
  s->kind = batch ? triangle::Job::Kind::Batch : triangle::Job::Kind::Clear;
  if (batch) s->batch = *batch;
  if (clear) s->clear = *clear;
  s->primitives = primitives;
  s->first_job = r.streamed_jobs_;
  r.streamed_jobs_ += (primitives + kTrianglesPerJob - 1) / kTrianglesPerJob;
  r.pool->stream_to(int(++r.streamed_used_));
  return true;
}

// On a worker: one streamed draw, its vertices then its jobs, as the vertex and triangle
// stages would run them at end_frame.
void CpuBackend::run_streamed(int item, int worker) {
  CpuBackend& r = *this;
  Streamed* s;
  {
    std::lock_guard lock(r.streamed_mutex_);
    s = &r.streamed_[size_t(item)];
  }
  const int w = r.framebuffer.width, h = r.framebuffer.height;
  if (s->kind == triangle::Job::Kind::Clear) {
    r.triangle_stage.run_job(r.bins, {triangle::Job::Kind::Clear, 0, 0, 1}, nullptr, &s->clear, s->first_job, worker, w, h);
    return;
  }
  geometry::BatchDrawPlan& d = s->batch;
  const size_t n = d.batch.vertex_count;
  if (s->projected.size() < n) s->projected.resize(n), s->codes.resize(n);
  geometry::ClipVertexJob v;
  v.positions = d.batch.position, v.begin = 0, v.end = n, v.viewport = d.viewport;
  v.out.projected = s->projected.data(), v.out.codes = s->codes.data();
  geometry::project_clip_vertices(v);
  d.projected = s->projected.data(), d.codes = s->codes.data();
  uint32_t number = s->first_job;
  for (uint32_t b = 0; b < s->primitives; b += kTrianglesPerJob)
    r.triangle_stage.run_job(r.bins, {triangle::Job::Kind::Batch, 0, b, std::min(b + kTrianglesPerJob, s->primitives)},
                             &d, nullptr, number++, worker, w, h);
}

// The rest of the stream, on the calling thread too; rethrows what a streamed draw threw.
void CpuBackend::close_stream() {
  may_stream_ = false;
  if (!stream_open_) return;
  stream_open_ = false;
  pool->close_stream();
}

// A stream whose frame will not be drawn: ended, whatever its draws threw.
void CpuBackend::drop_stream() noexcept {
  try {
    close_stream();
  } catch (...) {
  }
}

// The shadow maps of the frame's shadow-casting lights: each view's depth, drawn by a
// pipeline of its own (a CpuBackend at shadow_map_size a side, on this one's threads)
// with every mesh draw of the frame, unlit, the faces that face the light (both for a
// two-sided material: the bias of shading/shadow.hpp, not front-face culling, keeps lit
// surfaces clear of their own shadow). Then each light of the frame's EyeLights points
// at its maps.
void CpuBackend::render_shadows() {
  CpuBackend& r = *this;
  const int size = r.plan.options.shadow_map_size;
  plan_shadows(r.frame_lights_, r.view, r.caster_bounds_, size, r.shadow_lights_);
  r.depth_material_.shading = r.depth_two_sided_.shading = Shading::Unlit;
  r.depth_two_sided_.two_sided = true;
  RenderOptions o;
  o.threads = r.plan.options.threads;
  o.color = ColorPipeline::Display;
  // As the frame shades and culls (a cut-out caster is drawn with its own materials).
  o.shading = r.plan.options.shading;
  o.cull_back_faces = r.plan.options.cull_back_faces;
  FrameStart start;
  start.color = {0, 0, 0, 0};
  static const std::vector<Light> kNoLights;
  // The same casters, lights and camera as the last frame's: its maps are this one's.
  ShadowKey& key = r.next_shadow_key_;
  key.casters.clear(), key.views.clear();
  key.size = size, key.cull_back_faces = o.cull_back_faces;
  key.reusable = std::none_of(r.casters_.begin(), r.casters_.end(), [](const Caster& c) { return c.cut_out; });
  if (key.reusable)
    for (const Caster& c : r.casters_) key.casters.push_back({c.mesh, c.world, c.two_sided, geometry_fingerprint(*c.mesh)});
  for (const ShadowLight& s : r.shadow_lights_) key.views.insert(key.views.end(), s.views, s.views + s.faces);
  const bool keep = key.same_as(r.shadow_key_);
  r.shadow_key_.reusable = keep;  // maps half drawn (an error below) match nothing
  size_t pass = 0;
  for (ShadowLight& s : r.shadow_lights_)
    for (int f = 0; f < s.faces; ++f, ++pass) {
      if (pass == r.shadow_passes_.size()) r.shadow_passes_.push_back(std::make_unique<CpuBackend>(size, this));
      CpuBackend& b = *r.shadow_passes_[pass];
      if (keep) {
        s.shadow.face[f].depth = b.shadow_texels();
        continue;
      }
      b.resize(size, size, 1);
      // Never touched: the tiles draw depth in a scratch tile and store it as codes, and
      // no depth pass tests stencil.
      BlockVector<uint32_t>().swap(b.framebuffer.color);
      BlockVector<float>().swap(b.framebuffer.depth);
      BlockVector<uint8_t>().swap(b.framebuffer.stencil);
      const size_t texels = shading::shadow_codes_for(size);  // with the border and lines (shading/shadow.hpp)
      if (b.shadow_codes_.size() != texels) {
        b.shadow_codes_.assign(texels, uint16_t(shading::kShadowFar));
        std::fill(b.framebuffer.tile_clean.begin(), b.framebuffer.tile_clean.end(), 0);
      }
      b.shadow_map_ = &s.shadow.face[f];
      b.begin(s.views[f].view, s.views[f].projection, s.views[f].orthographic, kNoLights, start, o);
      for (const Caster& c : r.casters_)
        b.draw(*c.mesh, c.world, c.cut_out ? c.material : c.two_sided ? &r.depth_two_sided_ : &r.depth_material_, 0);
      b.run_frame(false);
      s.shadow.face[f].depth = b.shadow_texels();
    }
  std::swap(r.shadow_key_, key);
  r.plan.lights.shadows = !r.shadow_lights_.empty();
  for (const ShadowLight& s : r.shadow_lights_)
    (s.directional ? r.plan.lights.directional[s.index].shadow : r.plan.lights.point[s.index].shadow) = &s.shadow;
}

bool CpuBackend::ShadowKey::same_as(const ShadowKey& k) const {
  if (!reusable || !k.reusable || size != k.size || cull_back_faces != k.cull_back_faces) return false;
  if (casters != k.casters || views.size() != k.views.size()) return false;
  for (size_t i = 0; i < views.size(); ++i)
    if (!(views[i].view == k.views[i].view) || !(views[i].projection == k.views[i].projection) ||
        views[i].orthographic != k.views[i].orthographic)
      return false;
  return true;
}

// glTF's BLEND materials: their draws go after the opaque ones, farthest first (by the
// eye-space depth of their bounding sphere's centre), each between the clears it was
// recorded between; their own triangles keep their order.
void CpuBackend::order_blended_draws() {
  auto blended = [&](const triangle::Job& j) { return j.kind == triangle::Job::Kind::Mesh && plan.meshes[j.draw].blend; };
  if (std::none_of(jobs.begin(), jobs.end(), blended)) return;
  for (auto begin = jobs.begin(); begin != jobs.end();) {
    auto end = std::find_if(begin, jobs.end(), [](const triangle::Job& j) { return j.kind == triangle::Job::Kind::Clear; });
    auto mid = std::stable_partition(begin, end, [&](const triangle::Job& j) { return !blended(j); });
    std::stable_sort(mid, end, [&](const triangle::Job& a, const triangle::Job& b) {
      return plan.meshes[a.draw].centre.z < plan.meshes[b.draw].centre.z;  // more negative: farther
    });
    begin = end == jobs.end() ? end : end + 1;
  }
}

}  // namespace velocity
