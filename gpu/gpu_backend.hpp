// The GPU backend: velocity::Backend on OpenGL 3.3 core through EGL, or in a window's
// context (GlContextProvider), presenting there (gpu_backend.cpp).
#pragma once

#include <epoxy/gl.h>

#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "framebuffer/framebuffer.hpp"
#include "shading/lighting.hpp"
#include "shadows.hpp"
#include "velocity/backend.hpp"

namespace velocity {
class ThreadPool;
}

namespace velocity::gpu {

class Context;

class GpuBackend final : public Backend {
 public:
  // Throws velocity::Error (Context's) when no OpenGL 3.3 context can be made. With
  // `window`, draws with that context instead of an EGL one of its own.
  GpuBackend(int width, int height, bool hardware_only, GlContextProvider* window = nullptr);
  ~GpuBackend() override;

  // What drew: the GL version and renderer, and the EGL device or platform.
  const std::string& description() const;

  void resize(int w, int h) override { resize(w, h, ssaa_); }
  int width() const override { return width_; }
  int height() const override { return height_; }
  void begin_frame(const Camera& camera, const std::vector<Light>& lights, const FrameStart& start,
                   const RenderOptions& options) override;
  void draw(const Mesh& mesh, const Mat4& world, const Material* material, uint32_t object_id) override;
  void draw(const PrimitiveBatch& batch, const PixelState& state, uint32_t primitives) override;
  void clear(const ClearRequest& request) override;
  const FrameStats& end_frame() override;
  const FrameStats& stats() const override { return stats_; }

  Image color_image() const override;
  Image depth_image() const override;
  void read_color(uint8_t* rgba, size_t row_bytes, int channels) const override;
  void read_view_depth(float* out) const override;
  void read_window_depth(float* out) const override;
  void read_stencil(uint8_t* out) const override;
  std::vector<uint32_t> object_ids() const override;
  size_t framebuffer_bytes() const override;
  void present_window(int window_width, int window_height, const uint8_t* overlay) override;

  // Uploads so far (meshes and textures): a cached one is not uploaded again.
  size_t uploads() const { return uploads_; }

 private:
  struct MeshEntry;
  struct TextureEntry;
  // The frame as recorded (Backend: draws and clears run by end_frame), so that the
  // colour pipeline (RenderOptions::color's Auto: Linear when any draw is Pbr) is known
  // before the first pixel, and blended draws go after the opaque ones, as on the CPU.
  struct MeshDraw {
    const Mesh* mesh;
    MeshEntry* entry;
    Mat4 world;
    const Material* material;
    uint32_t object_id;
    bool blend;  // a glTF BLEND material: drawn after the opaque draws, far to near
    float depth; // eye-space z of the bounding sphere's centre (blended draws' order)
  };
  struct BatchDraw {
    PrimitiveBatch batch;
    PixelState state;
    uint32_t primitives;
  };
  struct Command {
    enum Kind { Mesh, Batch, Clear } kind;
    uint32_t index;
  };

  void resize(int w, int h, int k);
  GLuint program(bool affine, int primitive);
  GLuint pbr_program(bool affine);
  GLint uniform(GLuint program, const char* name);
  MeshEntry& mesh_entry(const Mesh& mesh);
  GLuint texture(const Texture& t, bool srgb = false);
  void set_budget();
  void reserve(size_t bytes, const std::string& what);
  void check_size(const Texture& t) const;
  void ensure_tangents(const Mesh& mesh, MeshEntry& m, int uv_set);
  void set_output(GLuint program, int output);
  void draw_pbr_slot(const Mesh& mesh, MeshEntry& m, const Material& mat, GLuint program);
  void draw_batch(const PrimitiveBatch& batch, const PixelState& state, uint32_t primitives);
  void run_clear(const ClearRequest& request);
  void replay();
  GLuint sampler(Filter filter, Wrap wrap);
  ThreadPool& pool() const;
  void fetch(unsigned what) const;
  bool direct_read(uint8_t* rgba, size_t row_bytes) const;
  bool resolve_on_gpu(uint8_t* rgba, size_t row_bytes) const;
  GLuint resolve_pass() const;
  void upload_lights(GLuint program);
  void draw_mesh(const Mesh& mesh, MeshEntry& m, const Mat4& world, const Material* override, uint32_t object_id,
                 const std::vector<std::pair<uint32_t, uint32_t>>* runs);
  void draw_painter();
  void render_shadows();
  void upload_shadows(GLuint program);
  void time_pass(int pass);
  void end_timing(bool read);
  void free(MeshEntry& m);
  void evict();
  template <class T>
  void scatter(const T* rows, T* tiled) const;

  std::unique_ptr<Context> context_;
  int width_ = 0, height_ = 0, ssaa_ = 0;
  int max_side_ = 0;
  GLint max_texture_ = 0;
  GLuint fbo_ = 0, renderbuffers_[3] = {};
  GLuint programs_[8] = {};  // [affine * 4 + primitive]
  GLuint pbr_programs_[2] = {};  // [affine]
  std::map<std::pair<GLuint, std::string>, GLint> uniforms_;
  std::unordered_map<const Mesh*, MeshEntry> meshes_;
  std::map<std::pair<const Texture*, bool>, TextureEntry> textures_;  // (texture, sRGB-decoded)
  std::unordered_map<int, GLuint> samplers_;
  size_t cache_bytes_ = 0, uploads_ = 0;
  size_t budget_ = 0, frame_bytes_ = 0;  // GPU memory: a frame's meshes and textures at most budget_
  std::string budget_source_;
  uint64_t frame_ = 0;

  RenderOptions options_;
  Mat4 view_, projection_, view_projection_, flipped_view_projection_;
  shading::EyeLights lights_;
  bool lights_uploaded_[10] = {};  // the mesh programs, then the Pbr ones
  bool orthographic_ = false;
  bool linear_ = false;  // the frame's colour pipeline (geometry::finish_color_plan)
  Material default_material_;
  std::vector<MeshDraw> mesh_draws_;
  std::vector<BatchDraw> batch_draws_;
  std::vector<ClearRequest> clears_;
  std::vector<Command> commands_;
  std::vector<uint32_t> painter_faces_;
  GLuint painter_indices_ = 0, order_buffer_ = 0, order_texture_ = 0;
  // pGL's path: its program, streamed arrays and samplers (by SamplerState).
  GLuint batch_programs_[2] = {};  // triangles and points, lines
  GLuint batch_vao_ = 0, batch_buffers_[6] = {};  // position, colour, texcoord, fog, indices, clip distances
  std::vector<uint32_t> batch_indices_;
  std::map<std::tuple<int, int, int, int, int, float, float, float, float>, GLuint> batch_samplers_;
  // Shadows (RenderOptions::shadows; CpuBackend::render_shadows): every mesh draw of the
  // frame casts, seen or not; the maps are layers of one depth texture.
  struct Caster {
    MeshEntry* entry;
    Mat4 world;
    bool two_sided;
  };
  std::vector<Light> frame_lights_;
  std::vector<Caster> casters_;
  Sphere caster_bounds_{{}, -1};
  std::vector<ShadowLight> shadow_lights_;
  GLuint shadow_fbo_ = 0, shadow_maps_ = 0, depth_program_ = 0;
  int shadow_size_ = 0, shadow_layers_ = 0;
  // The GPU's own time per pass (FrameStats::gpu_*_ms): GL_TIME_ELAPSED queries, one
  // running at a time (GL's rule), a pass's several summed after the frame's glFinish.
  enum Pass { kShadowPass, kOpaquePass, kBlendPass };
  int timing_ = -1;  // the pass being timed, -1 none
  std::vector<std::pair<int, GLuint>> queries_;  // this frame's, in order
  std::vector<GLuint> spare_queries_;
  mutable std::unique_ptr<ThreadPool> pool_;
  FrameStats stats_;
  std::chrono::steady_clock::time_point t0_;

  // The last frame, read back plane by plane as the reads ask (fetch): pending_ says
  // which planes the GPU still holds alone. Reads may come from any thread, one
  // renderer at a time, so fetching is under a lock.
  enum Plane : unsigned { kColor = 1, kDepth = 2, kIds = 4, kStencil = 8 };
  mutable std::mutex fetch_mutex_;
  mutable unsigned pending_ = 0;
  mutable double reads_ms_ = 0;  // the read-backs since the last end_frame
  mutable double gpu_reads_ms_ = 0;  // their GPU time (read_query_)
  mutable GLuint read_query_ = 0;
  // The super-sampling resolve on the GPU (resolve_on_gpu): a copy of the samples as a
  // texture, the w x h output, their framebuffers and the pass's program.
  struct Resolve {
    GLuint program = 0, vao = 0, samples = 0, output = 0, framebuffers[2] = {};
    int width = 0, height = 0, ssaa = 0;
  };
  mutable Resolve resolve_;
  // present_window: the 2D layer's texture and the program that blends it on.
  struct Overlay {
    GLuint program = 0, vao = 0, texture = 0;
    int width = 0, height = 0;
  };
  Overlay overlay_;
  mutable Framebuffer samples_;
  mutable std::vector<uint32_t> rows_;
  mutable std::vector<float> depth_rows_;
  mutable std::vector<uint8_t> stencil_rows_;
  bool stencil_used_ = false;  // the frame cleared or wrote the stencil: fetch it
};

}  // namespace velocity::gpu
