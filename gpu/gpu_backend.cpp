// The GPU backend (velocity/backend.hpp) on OpenGL 3.3 core: the same frame as the CPU
// pipeline (src/frame.cpp), drawn by the GPU into a framebuffer object of the sample
// size (output x ssaa), then read back whole into a CPU Framebuffer, so that every
// read-back (colour, the ssaa box resolve, view and window depth, object ids) is the CPU
// pipeline's own code on the same samples.
//
// What is uploaded when (docs/gpu.md): a mesh the first frame it is drawn, again only
// when its contents change (a 64-bit fingerprint of every array it has, computed once a
// frame on the renderer's threads); a texture and its mip levels the first frame it is read, again when its texels
// change (the same fingerprint); lights and camera every frame (uniforms). Entries not
// used for kEvictFrames frames, and the least recently used ones beyond the budget
// bytes, are deleted.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <thread>
#include <unordered_map>
#include <vector>

#include "context.hpp"
#include "core/thread_pool.hpp"
#include "framebuffer/framebuffer.hpp"
#include "framebuffer/read_back.hpp"
#include "framebuffer/resolve.hpp"
#include "geometry/draw_plan.hpp"
#include "geometry/normals.hpp"
#include "geometry/object_cull.hpp"
#include "geometry/tangents.hpp"
#include "gpu_backend.hpp"
#include "shaders.hpp"
#include "shading/ggx_albedo.hpp"
#include "shading/lighting.hpp"
#include "velocity/error.hpp"

namespace velocity::gpu {

namespace {

constexpr uint64_t kEvictFrames = 120;
constexpr size_t kCacheBudget = size_t(1) << 30;  // 1 GiB of meshes and textures, where the driver does not say

std::string mib(size_t bytes) { return std::to_string((bytes + (size_t(1) << 20) - 1) >> 20); }

// A 64-bit fingerprint of bytes: four independent multiply-xor lanes (memory speed).
struct Fingerprint {
  uint64_t lane[4] = {0x9E3779B97F4A7C15ull, 0xC2B2AE3D27D4EB4Full, 0x165667B19E3779F9ull, 0x27D4EB2F165667C5ull};
  void add(const void* data, size_t bytes) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    size_t i = 0;
    for (; i + 32 <= bytes; i += 32)
      for (int k = 0; k < 4; ++k) {
        uint64_t w;
        std::memcpy(&w, p + i + 8 * k, 8);
        lane[k] = (lane[k] ^ w) * 0x100000001B3ull;
        lane[k] ^= lane[k] >> 29;
      }
    uint64_t tail = bytes;
    for (; i < bytes; ++i) tail = (tail ^ p[i]) * 0x100000001B3ull;
    lane[0] = (lane[0] ^ tail) * 0x9E3779B97F4A7C15ull;
  }
  template <class T>
  void add(const std::vector<T>& v) {
    const uint64_t n = v.size();
    add(&n, sizeof n);
    if (!v.empty()) add(v.data(), v.size() * sizeof(T));
  }
  uint64_t value() const { return lane[0] ^ (lane[1] * 3) ^ (lane[2] * 5) ^ (lane[3] * 7); }
};

// The fingerprint of several arrays, hashed in chunks on a thread pool: every frame
// checks every byte of what it draws (10 M triangles are some 300 MB), which one thread
// does at a few GB/s. The sizes go in first, then each chunk's own fingerprint in
// order, so the value does not depend on the number of threads.
class ChunkedFingerprint {
 public:
  template <class T>
  void add(const std::vector<T>& v) {
    const uint64_t n = v.size();
    sizes_.add(&n, sizeof n);
    const unsigned char* p = reinterpret_cast<const unsigned char*>(v.data());
    const size_t bytes = v.size() * sizeof(T);
    for (size_t at = 0; at < bytes; at += kChunk) chunks_.push_back({p + at, std::min(kChunk, bytes - at)});
  }
  void add_size(uint64_t n) { sizes_.add(&n, sizeof n); }
  uint64_t value(ThreadPool& pool) {
    std::vector<uint64_t> values(chunks_.size());
    pool.run(int(chunks_.size()), [&](int i) {
      Fingerprint f;
      f.add(chunks_[size_t(i)].first, chunks_[size_t(i)].second);
      values[size_t(i)] = f.value();
    });
    Fingerprint f = sizes_;
    if (!values.empty()) f.add(values.data(), values.size() * sizeof(uint64_t));
    return f.value();
  }

 private:
  static constexpr size_t kChunk = size_t(1) << 20;
  Fingerprint sizes_;
  std::vector<std::pair<const unsigned char*, size_t>> chunks_;
};

uint64_t fingerprint(const Mesh& m, ThreadPool& pool) {
  ChunkedFingerprint f;
  f.add(m.positions), f.add(m.normals), f.add(m.uvs), f.add(m.colors), f.add(m.triangles);
  f.add(m.uvs1), f.add(m.tangents), f.add(m.alphas);
  f.add(m.face_colors), f.add(m.face_materials);
  f.add_size(m.materials.size());
  return f.value(pool);
}

uint64_t fingerprint(const Texture& t, ThreadPool& pool) {
  ChunkedFingerprint f;
  for (const Texture::Level& l : t.levels()) f.add_size(uint64_t(l.width)), f.add_size(uint64_t(l.height)), f.add(l.texels);
  return f.value(pool);
}

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

// Adds the time from construction to destruction to `total` (a stage's time, over the
// calls that make it up).
class StageTimer {
 public:
  explicit StageTimer(double& total) : total_(total) {}
  ~StageTimer() { total_ += ms_since(t0_); }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  double& total_;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

// Adds the GPU's time for the GL calls from construction to destruction to `total`
// (GL_TIME_ELAPSED; the calls are read-backs, which wait for the GPU anyway).
class GpuTimer {
 public:
  GpuTimer(GLuint& query, double& total) : query_(query), total_(total) {
    if (!query_) glGenQueries(1, &query_);
    glBeginQuery(GL_TIME_ELAPSED, query_);
  }
  ~GpuTimer() {
    glEndQuery(GL_TIME_ELAPSED);
    GLuint64 ns = 0;
    glGetQueryObjectui64v(query_, GL_QUERY_RESULT, &ns);
    total_ += double(ns) * 1e-6;
  }
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

 private:
  GLuint& query_;
  double& total_;
};

void upload_matrix(GLint at, const Mat4& m) { glUniformMatrix4fv(at, 1, GL_TRUE, &m.m[0][0]); }

// KHR_texture_transform as two rows of an affine map (geometry/draw_plan.cpp's uv_affine).
void uv_map_rows(const UvTransform& t, float* rows) {
  const float c = std::cos(t.rotation), s = std::sin(t.rotation);
  const float r[6] = {c * t.scale.x, s * t.scale.y, t.offset.x, -s * t.scale.x, c * t.scale.y, t.offset.y};
  std::copy(r, r + 6, rows);
}

// The uv set a Pbr material's textures read (geometry/draw_plan.cpp's pbr_uv_set).
int pbr_uv_set(const Material& mat) {
  if (mat.texture) return mat.texture_uv.uv_set;
  for (const TextureRef* t : {&mat.pbr.metallic_roughness, &mat.pbr.normal, &mat.pbr.occlusion, &mat.pbr.emissive_map})
    if (*t) return t->uv.uv_set;
  return 0;
}

// geometry::pipeline_color as the shaders' to_pipeline() takes it: 0 as it is, 1 decode
// sRGB, 2 encode.
int color_convert(ColorSpace space, bool linear) {
  if (linear == (space == ColorSpace::Linear)) return 0;
  return linear ? 1 : 2;
}

// The GL error, if any, as velocity::Error; an allocation the device refused names what.
void check_gl(const char* what) {
  GLenum e = glGetError(), first = e;
  while (e != GL_NO_ERROR) e = glGetError();  // drain: GL may hold several
  if (first == GL_OUT_OF_MEMORY) throw Error(std::string(what) + ": the GPU is out of memory");
  if (first != GL_NO_ERROR) {
    char s[64];
    std::snprintf(s, sizeof s, ": OpenGL error 0x%04x", unsigned(first));
    throw Error(std::string(what) + s);
  }
}

}  // namespace

struct GpuBackend::MeshEntry {
  // What was uploaded: the mesh's revision (Mesh::revision), or 0 and its fingerprint.
  uint64_t revision = 0, fingerprint = 0, last_frame = 0;
  size_t bytes = 0;
  // positions, normals, uvs, colours, indices, face colours, second uvs, tangents, alphas
  GLuint vao = 0, buffers[9] = {}, face_colors = 0;
  bool has_uvs = false, has_colors = false, has_face_colors = false, has_uvs1 = false, has_alphas = false;
  int tangent_uv_set = -1;  // the tangents in buffers[7]: the mesh's (2), generated from a uv set (0, 1), none (-1)
  // Faces reordered by material slot (triangle/mesh_job.cpp's slot_of): slot s draws
  // faces [slot_begin[s], slot_begin[s + 1]); `face_of` maps back to the mesh's faces.
  std::vector<uint32_t> slot_begin;
  std::vector<uint32_t> face_of;
};

struct GpuBackend::TextureEntry {
  uint64_t fingerprint = 0, last_frame = 0;
  size_t bytes = 0;
  GLuint texture = 0;
};

GpuBackend::GpuBackend(int width, int height, bool hardware_only, GlContextProvider* window)
    : context_(window ? std::make_unique<Context>(*window, hardware_only) : std::make_unique<Context>(hardware_only)) {
  Current current(*context_);
  glGenFramebuffers(1, &fbo_);
  glGenRenderbuffers(3, renderbuffers_);
  GLint max_side = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_side);
  max_side_ = std::min(int(max_side), kMaxFramebufferSide);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture_);
  set_budget();
  check_gl("the GPU backend's set-up");
  resize(width, height, 1);
}

const std::string& GpuBackend::description() const { return context_->description(); }

// The GPU memory the meshes and textures of one frame may take: VELOCITY_GPU_MEMORY_MB
// when set; else three quarters of what the driver reports (GL_NVX_gpu_memory_info,
// GL_ATI_meminfo); else 1 GiB. A mesh or texture over it, or a frame whose meshes and
// textures together are, is an error that says so (reserve); the cache is trimmed to it.
void GpuBackend::set_budget() {
  budget_ = kCacheBudget, budget_source_ = "the default: the driver does not report its memory";
  if (const char* env = std::getenv("VELOCITY_GPU_MEMORY_MB"); env && *env) {
    char* end = nullptr;
    const unsigned long long mb = std::strtoull(env, &end, 10);
    if (*end != '\0' || mb == 0 || mb > (1ull << 24))
      throw Error(std::string("VELOCITY_GPU_MEMORY_MB: expected a number of MiB (1..16777216), got '") + env + "'");
    budget_ = size_t(mb) << 20, budget_source_ = "VELOCITY_GPU_MEMORY_MB";
    return;
  }
  GLint kib[4] = {};
  if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
    glGetIntegerv(0x9048, kib);  // GL_GPU_MEMORY_INFO_TOTAL_AVAILABLE_MEMORY_NVX
    if (kib[0] > 0) budget_source_ = "3/4 of the device's " + mib(size_t(kib[0]) << 10) + " MiB (GL_NVX_gpu_memory_info)";
  } else if (epoxy_has_gl_extension("GL_ATI_meminfo")) {
    glGetIntegerv(0x87FC, kib);  // GL_TEXTURE_FREE_MEMORY_ATI: total free first
    if (kib[0] > 0) budget_source_ = "3/4 of the device's free " + mib(size_t(kib[0]) << 10) + " MiB (GL_ATI_meminfo)";
  }
  if (kib[0] > 0) budget_ = (size_t(kib[0]) << 10) / 4 * 3;
}

// Counts `bytes` more of GPU memory for this frame, or says what is too large.
void GpuBackend::reserve(size_t bytes, const std::string& what) {
  if (bytes > budget_)
    throw Error(what + " needs " + mib(bytes) + " MiB of GPU memory, more than the GPU backend's budget of " +
                mib(budget_) + " MiB (" + budget_source_ + ")");
  if (frame_bytes_ + bytes > budget_)
    throw Error("the frame's meshes and textures need over " + mib(frame_bytes_ + bytes) +
                " MiB of GPU memory (at " + what + "), more than the GPU backend's budget of " + mib(budget_) +
                " MiB (" + budget_source_ + ")");
  frame_bytes_ += bytes;
}

// A texture the GPU cannot hold (GL_MAX_TEXTURE_SIZE) is an error when it is drawn.
void GpuBackend::check_size(const Texture& t) const {
  if (t.width() > max_texture_ || t.height() > max_texture_)
    throw Error("a " + std::to_string(t.width()) + "x" + std::to_string(t.height()) +
                " texture is larger than the GPU takes (" + std::to_string(max_texture_) + " a side)");
}

GpuBackend::~GpuBackend() {
  try {
    Current current(*context_);
    for (auto& [key, m] : meshes_) free(m);
    for (auto& [key, t] : textures_) glDeleteTextures(1, &t.texture);
    for (auto& [key, s] : samplers_) glDeleteSamplers(1, &s);
    for (GLuint p : programs_)
      if (p) glDeleteProgram(p);
    for (GLuint p : pbr_programs_)
      if (p) glDeleteProgram(p);
    glDeleteFramebuffers(1, &fbo_);
    if (shadow_fbo_) glDeleteFramebuffers(1, &shadow_fbo_), glDeleteTextures(1, &shadow_maps_), glDeleteProgram(depth_program_);
    glDeleteRenderbuffers(3, renderbuffers_);
    if (resolve_.program) {
      glDeleteProgram(resolve_.program), glDeleteVertexArrays(1, &resolve_.vao), glDeleteTextures(1, &resolve_.samples);
      glDeleteRenderbuffers(1, &resolve_.output), glDeleteFramebuffers(2, resolve_.framebuffers);
    }
    if (overlay_.program)
      glDeleteProgram(overlay_.program), glDeleteVertexArrays(1, &overlay_.vao), glDeleteTextures(1, &overlay_.texture);
    glDeleteBuffers(1, &order_buffer_), glDeleteTextures(1, &order_texture_), glDeleteBuffers(1, &painter_indices_);
    for (auto& [key, s] : batch_samplers_) glDeleteSamplers(1, &s);
    for (GLuint p : batch_programs_)
      if (p) glDeleteProgram(p);
    if (batch_vao_) glDeleteVertexArrays(1, &batch_vao_), glDeleteBuffers(6, batch_buffers_);
    for (const auto& [pass, q] : queries_) spare_queries_.push_back(q);
    if (!spare_queries_.empty()) glDeleteQueries(GLsizei(spare_queries_.size()), spare_queries_.data());
    if (read_query_) glDeleteQueries(1, &read_query_);
  } catch (const Error&) {
    // A context that cannot be made current any more: its objects go with it.
  }
}

void GpuBackend::free(MeshEntry& m) {
  glDeleteVertexArrays(1, &m.vao);
  glDeleteBuffers(9, m.buffers);
  glDeleteTextures(1, &m.face_colors);
}

void GpuBackend::resize(int w, int h, int k) {
  if (k < 1 || k > 4) throw Error("super-sampling factor " + std::to_string(k) + " is out of range (1..4)");
  if (w < 1 || h < 1 || w > kMaxFramebufferSide || h > kMaxFramebufferSide)
    throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range (1.." +
                std::to_string(kMaxFramebufferSide) + " a side)");
  if (int64_t(w) * k > max_side_ || int64_t(h) * k > max_side_)
    throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " with " + std::to_string(k) + "x" +
                std::to_string(k) + " super-sampling needs a sample buffer over " + std::to_string(max_side_) +
                " a side (the GPU's or the renderer's limit)");
  if (w == width_ && h == height_ && k == ssaa_) return;
  // The CPU copy first: when memory runs out nothing has changed. The last frame goes
  // (as the CPU's does): nothing is left to read back.
  samples_.resize(w * k, h * k);
  pending_ = 0;
  Current current(*context_);
  const int sw = w * k, sh = h * k;
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, sw, sh);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_R32UI, sw, sh);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[2]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH32F_STENCIL8, sw, sh);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[0]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, renderbuffers_[1]);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, renderbuffers_[2]);
  stencil_used_ = true;  // (read back at the next frame: the new buffer's contents)
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  check_gl("the GPU framebuffer");
  if (status != GL_FRAMEBUFFER_COMPLETE) throw Error("the GPU framebuffer is incomplete at " + std::to_string(sw) + "x" + std::to_string(sh));
  width_ = w, height_ = h, ssaa_ = k;
}

GLuint GpuBackend::program(bool affine, int primitive) {
  GLuint& p = programs_[(affine ? 4 : 0) + primitive];
  if (!p) p = build_mesh_program(affine, primitive);
  return p;
}

GLuint GpuBackend::pbr_program(bool affine) {
  GLuint& p = pbr_programs_[affine ? 1 : 0];
  if (!p) p = build_pbr_program(affine);
  return p;
}

GLint GpuBackend::uniform(GLuint program, const char* name) {
  auto key = std::make_pair(program, std::string(name));
  auto it = uniforms_.find(key);
  if (it != uniforms_.end()) return it->second;
  const GLint at = glGetUniformLocation(program, name);
  uniforms_.emplace(std::move(key), at);
  return at;
}

void GpuBackend::begin_frame(const Camera& camera, const std::vector<Light>& lights, const FrameStart& start,
                             const RenderOptions& options) {
  if (options.shadows && (options.shadow_map_size < 16 || options.shadow_map_size > 8192))
    throw Error("shadow map size " + std::to_string(options.shadow_map_size) + " is out of range (16..8192)");
  resize(width_, height_, options.ssaa);
  options_ = options;
  stats_ = {};
  frame_++;
  t0_ = std::chrono::steady_clock::now();
  const int w = width_ * ssaa_, h = height_ * ssaa_;
  view_ = camera.view();
  projection_ = camera.projection_matrix(float(w) / float(h));
  // Row 0 of the image at the top: the framebuffer is drawn upside down (y flipped,
  // so front faces turn clockwise), and read back row 0 first.
  Mat4 flip;
  flip.m[1][1] = -1;
  flipped_view_projection_ = flip * projection_ * view_;
  view_projection_ = projection_ * view_;
  shading::eye_lights(view_, lights, lights_);
  // The lights that may cast (CpuBackend::begin_frame): no lights, kDefaultLight's
  // directional light (given in eye space) casts.
  casters_.clear();
  caster_bounds_ = {{}, -1};
  shadow_lights_.clear();
  if (options.shadows) frame_lights_ = lights;
  if (options.shadows && lights.empty()) {
    const Mat4& v = view_;
    const Vec3 t = normalize(kDefaultLight.towards);
    frame_lights_ = {Light::directional({v.m[0][0] * t.x + v.m[1][0] * t.y + v.m[2][0] * t.z,
                                         v.m[0][1] * t.x + v.m[1][1] * t.y + v.m[2][1] * t.z,
                                         v.m[0][2] * t.x + v.m[1][2] * t.y + v.m[2][2] * t.z},
                                        kDefaultLight.diffuse)};
  }
  if (lights_.directional.size() > size_t(kMaxLights) || lights_.point.size() > size_t(kMaxLights))
    throw Error("the GPU backend takes at most " + std::to_string(kMaxLights) + " directional and " +
                std::to_string(kMaxLights) + " point lights");
  for (bool& u : lights_uploaded_) u = false;
  orthographic_ = camera.projection == Projection::Orthographic;
  frame_bytes_ = 0;
  mesh_draws_.clear(), batch_draws_.clear(), clears_.clear(), commands_.clear();

  context_->make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  const GLenum outputs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, outputs);
  glViewport(0, 0, w, h);
  glDisable(GL_SCISSOR_TEST), glDisable(GL_BLEND);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE), glDepthMask(GL_TRUE);
  if (start.clear_color_buffer) {
    const float c[4] = {start.color.x, start.color.y, start.color.z, start.color.w};
    const GLuint zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, c);
    glClearBufferuiv(GL_COLOR, 1, zero);
  }
  if (start.clear_depth_buffer) {
    const float d = std::clamp(start.depth, 0.0f, 1.0f);
    glClearBufferfv(GL_DEPTH, 0, &d);
  }
  glDisable(GL_STENCIL_TEST), glStencilMask(0xff);
  if (start.clear_stencil_buffer) {
    const GLint value = start.stencil;
    glClearBufferiv(GL_STENCIL, 0, &value);
    stencil_used_ = true;
  }
  glFrontFace(GL_CW);  // (the flip above)
  if (options.depth_mode == DepthMode::Painter) {
    glDisable(GL_DEPTH_TEST);
  } else {
    glEnable(GL_DEPTH_TEST), glDepthFunc(GL_LESS);
  }
}

GpuBackend::MeshEntry& GpuBackend::mesh_entry(const Mesh& mesh) {
  // Checked once a frame: a mesh stays unchanged until end_frame (Renderer::draw's rule),
  // so its copies in the same frame cost no second pass over its bytes.
  auto it = meshes_.find(&mesh);
  if (it != meshes_.end() && it->second.last_frame == frame_) return it->second;
  StageTimer timer(stats_.upload_ms);
  // A marked mesh (Mesh::revision) is trusted; an unmarked one is hashed.
  const uint64_t key = mesh.revision ? 0 : fingerprint(mesh, pool());
  if (!mesh.revision) stats_.meshes_hashed++;
  if (it != meshes_.end() && it->second.revision == mesh.revision && it->second.fingerprint == key) {
    reserve(it->second.bytes, "mesh '" + mesh.name + "'");
    it->second.last_frame = frame_;
    return it->second;
  }
  if (it != meshes_.end()) free(it->second), cache_bytes_ -= it->second.bytes, meshes_.erase(it);
  {
    // What the upload below takes (the tangents a normal map may add come later).
    const size_t nv = mesh.positions.size(), nt = mesh.triangles.size();
    size_t per_vertex = 24;
    if (mesh.uvs.size() == nv) per_vertex += 8;
    if (mesh.colors.size() == nv) per_vertex += 12;
    if (mesh.uvs1.size() == nv) per_vertex += 8;
    if (mesh.tangents.size() == nv) per_vertex += 16;
    if (mesh.alphas.size() == nv) per_vertex += 4;
    reserve(nv * per_vertex + nt * (mesh.face_colors.empty() ? 12 : 24), "mesh '" + mesh.name + "'");
  }
  uploads_++;

  MeshEntry m;
  m.revision = mesh.revision, m.fingerprint = key, m.last_frame = frame_;
  const size_t nv = mesh.positions.size(), nt = mesh.triangles.size();
  // Faces by material slot, in mesh order within a slot.
  const size_t slots = 1 + mesh.materials.size();
  auto slot_of = [&](size_t f) -> uint32_t {
    if (!mesh.face_materials.empty()) {
      const uint32_t s = f < mesh.face_materials.size() ? mesh.face_materials[f] + 1 : 0;
      return s < slots ? s : 0;
    }
    return mesh.materials.empty() ? 0 : 1;
  };
  m.slot_begin.assign(slots + 1, 0);
  for (size_t f = 0; f < nt; ++f) m.slot_begin[slot_of(f) + 1]++;
  for (size_t s = 0; s < slots; ++s) m.slot_begin[s + 1] += m.slot_begin[s];
  m.face_of.resize(nt);
  std::vector<uint32_t> next(m.slot_begin.begin(), m.slot_begin.end() - 1);
  for (size_t f = 0; f < nt; ++f) m.face_of[next[slot_of(f)]++] = uint32_t(f);
  std::vector<uint32_t> indices(nt * 3);
  for (size_t i = 0; i < nt; ++i)
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.triangles[m.face_of[i]].v[k];
      indices[i * 3 + size_t(k)] = v < nv ? v : 0;
    }

  std::vector<Vec3> averaged;
  const std::vector<Vec3>* normals = &mesh.normals;
  if (mesh.normals.size() != nv) geometry::average_normals(mesh, averaged), normals = &averaged;

  glGenVertexArrays(1, &m.vao);
  glGenBuffers(9, m.buffers);
  glBindVertexArray(m.vao);
  // Attribute locations: the shaders' (kMeshVertexInputs, kPbrVertex); buffers: MeshEntry's.
  auto attribute = [&](int location, int buffer, const void* data, size_t bytes, int components) {
    glBindBuffer(GL_ARRAY_BUFFER, m.buffers[buffer]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(bytes), data, GL_STATIC_DRAW);
    glVertexAttribPointer(GLuint(location), components, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(GLuint(location));
    m.bytes += bytes;
  };
  attribute(0, 0, mesh.positions.data(), nv * sizeof(Vec3), 3);
  attribute(1, 1, normals->data(), nv * sizeof(Vec3), 3);
  m.has_uvs = mesh.uvs.size() == nv && nv;
  if (m.has_uvs) attribute(2, 2, mesh.uvs.data(), nv * sizeof(Vec2), 2);
  m.has_colors = mesh.colors.size() == nv && nv;
  if (m.has_colors) attribute(3, 3, mesh.colors.data(), nv * sizeof(Vec3), 3);
  m.has_uvs1 = mesh.uvs1.size() == nv && nv;
  if (m.has_uvs1) attribute(4, 6, mesh.uvs1.data(), nv * sizeof(Vec2), 2);
  if (mesh.tangents.size() == nv && nv) attribute(5, 7, mesh.tangents.data(), nv * sizeof(Vec4), 4), m.tangent_uv_set = 2;
  m.has_alphas = mesh.alphas.size() == nv && nv;
  if (m.has_alphas) attribute(6, 8, mesh.alphas.data(), nv * sizeof(float), 1);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.buffers[4]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * 4), indices.data(), GL_STATIC_DRAW);
  m.bytes += indices.size() * 4;
  glBindVertexArray(0);
  m.has_face_colors = !mesh.face_colors.empty();
  if (m.has_face_colors) {
    std::vector<Vec3> colors(nt);
    for (size_t i = 0; i < nt; ++i) colors[i] = m.face_of[i] < mesh.face_colors.size() ? mesh.face_colors[m.face_of[i]] : Vec3{};
    glBindBuffer(GL_TEXTURE_BUFFER, m.buffers[5]);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(nt * sizeof(Vec3)), colors.data(), GL_STATIC_DRAW);
    glGenTextures(1, &m.face_colors);
    glBindTexture(GL_TEXTURE_BUFFER, m.face_colors);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGB32F, m.buffers[5]);
    m.bytes += nt * sizeof(Vec3);
  }
  try {
    check_gl(("uploading mesh '" + mesh.name + "' (" + std::to_string(m.bytes >> 20) + " MiB)").c_str());
  } catch (const Error&) {
    free(m);
    throw;
  }
  cache_bytes_ += m.bytes;
  return meshes_.emplace(&mesh, std::move(m)).first->second;
}

// A colour texture in a Linear frame is uploaded as GL_SRGB8_ALPHA8: the driver decodes
// each texel before filtering, as the CPU's sampler does (SamplerView::srgb); the same
// Texture read both ways is two entries.
GLuint GpuBackend::texture(const Texture& t, bool srgb) {
  auto it = textures_.find({&t, srgb});
  if (it != textures_.end() && it->second.last_frame == frame_) return it->second.texture;  // (as meshes)
  StageTimer timer(stats_.upload_ms);
  const uint64_t key = fingerprint(t, pool());
  const std::string what = "a " + std::to_string(t.width()) + "x" + std::to_string(t.height()) + " texture";
  if (it != textures_.end() && it->second.fingerprint == key) {
    reserve(it->second.bytes, what);
    it->second.last_frame = frame_;
    return it->second.texture;
  }
  if (it != textures_.end()) glDeleteTextures(1, &it->second.texture), cache_bytes_ -= it->second.bytes, textures_.erase(it);
  check_size(t);
  size_t bytes = 0;
  for (const Texture::Level& l : t.levels()) bytes += l.texels.size() * 4;
  reserve(bytes, what);
  uploads_++;
  TextureEntry e;
  e.fingerprint = key, e.last_frame = frame_;
  glGenTextures(1, &e.texture);
  glBindTexture(GL_TEXTURE_2D, e.texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // The texture's own mip levels (Texture's box filter), not the driver's.
  const auto& levels = t.levels();
  for (size_t l = 0; l < levels.size(); ++l) {
    glTexImage2D(GL_TEXTURE_2D, GLint(l), srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, levels[l].width, levels[l].height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 levels[l].texels.data());
    e.bytes += levels[l].texels.size() * 4;
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(levels.size()) - 1);
  try {
    check_gl("uploading a texture");
  } catch (const Error&) {
    glDeleteTextures(1, &e.texture);
    throw;
  }
  cache_bytes_ += e.bytes;
  return textures_.emplace(std::make_pair(&t, srgb), e).first->second.texture;
}

// The renderer's threads (RenderOptions::threads: 0 is every core), for the fingerprints.
ThreadPool& GpuBackend::pool() const {
  int threads = options_.threads > 0 ? options_.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::min(threads, 256);
  // A pool made before this process was forked has no workers here: a new one.
  if (!pool_ || pool_->size() != threads || pool_->orphaned()) pool_ = std::make_unique<ThreadPool>(threads);
  return *pool_;
}

GLuint GpuBackend::sampler(Filter filter, Wrap wrap) {
  const int key = int(filter) * 8 + int(wrap);
  auto it = samplers_.find(key);
  if (it != samplers_.end()) return it->second;
  GLuint s = 0;
  glGenSamplers(1, &s);
  const GLint mag = filter == Filter::Nearest ? GL_NEAREST : GL_LINEAR;
  const GLint min = filter == Filter::Nearest ? GL_NEAREST : filter == Filter::Bilinear ? GL_LINEAR : GL_LINEAR_MIPMAP_LINEAR;
  const GLint w = wrap == Wrap::Repeat ? GL_REPEAT : wrap == Wrap::Clamp ? GL_CLAMP_TO_EDGE
                  : wrap == Wrap::MirroredRepeat ? GL_MIRRORED_REPEAT : GL_CLAMP_TO_BORDER;
  glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, mag), glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, min);
  glSamplerParameteri(s, GL_TEXTURE_WRAP_S, w), glSamplerParameteri(s, GL_TEXTURE_WRAP_T, w);
  samplers_.emplace(key, s);
  return s;
}

void GpuBackend::upload_lights(GLuint p) {
  const shading::EyeLights& l = lights_;
  glUniform3f(uniform(p, "u_ambient"), l.ambient.x, l.ambient.y, l.ambient.z);
  if (const GLint albedo = uniform(p, "u_ggx_albedo[0]"); albedo >= 0)  // PBR programs only
    glUniform1fv(albedo, shading::kGgxAlbedoSize * shading::kGgxAlbedoSize, shading::ggx_albedo_table());
  glUniform1i(uniform(p, "u_directional_count"), GLint(l.directional.size()));
  glUniform1i(uniform(p, "u_point_count"), GLint(l.point.size()));
  upload_shadows(p);
  std::vector<Vec3> a, b, c;
  for (const auto& d : l.directional) a.push_back(d.to_light), b.push_back(d.color);
  if (!a.empty()) {
    glUniform3fv(uniform(p, "u_directional_to_light"), GLsizei(a.size()), &a[0].x);
    glUniform3fv(uniform(p, "u_directional_color"), GLsizei(b.size()), &b[0].x);
  }
  a.clear(), b.clear();
  std::vector<Vec3> falloff, axis;
  std::vector<Vec2> cone;
  for (const auto& pl : l.point) {
    a.push_back(pl.position), b.push_back(pl.color), c.push_back({pl.constant, pl.linear, pl.quadratic});
    falloff.push_back({pl.inverse_square ? 1.0f : 0.0f, pl.inv_range4, pl.spot ? 1.0f : 0.0f});
    axis.push_back(pl.spot_axis), cone.push_back({pl.spot_scale, pl.spot_offset});
  }
  if (!a.empty()) {
    glUniform3fv(uniform(p, "u_point_position"), GLsizei(a.size()), &a[0].x);
    glUniform3fv(uniform(p, "u_point_color"), GLsizei(b.size()), &b[0].x);
    glUniform3fv(uniform(p, "u_point_attenuation"), GLsizei(c.size()), &c[0].x);
    glUniform3fv(uniform(p, "u_point_falloff"), GLsizei(falloff.size()), &falloff[0].x);
    glUniform3fv(uniform(p, "u_point_spot_axis"), GLsizei(axis.size()), &axis[0].x);
    glUniform2fv(uniform(p, "u_point_spot_cone"), GLsizei(cone.size()), &cone[0].x);
  }
}

// The frame's shadow maps (CpuBackend::render_shadows): the views of src/shadows.cpp,
// each drawn into a layer of one depth texture with every caster, depth only, the
// faces turned towards the light (both for a two-sided draw), in the frame's flipped
// orientation so that a map's row 0 is the CPU's (kLightingGlsl reads it as the CPU
// does). Then the frame's framebuffer and state again.
void GpuBackend::render_shadows() {
  const int size = options_.shadow_map_size;
  plan_shadows(frame_lights_, view_, caster_bounds_, size, shadow_lights_);
  int layers = 0;
  for (const ShadowLight& l : shadow_lights_) layers += l.faces;
  if (layers == 0) return;
  if (size > max_texture_)
    throw Error("a shadow map of " + std::to_string(size) + " texels a side is larger than the GPU takes (" +
                std::to_string(max_texture_) + ")");
  reserve(size_t(size) * size_t(size) * 4 * size_t(layers), "the shadow maps");
  if (!shadow_fbo_) glGenFramebuffers(1, &shadow_fbo_);
  if (!depth_program_) depth_program_ = build_depth_program();
  if (size != shadow_size_ || layers > shadow_layers_) {
    if (shadow_maps_) glDeleteTextures(1, &shadow_maps_);
    glGenTextures(1, &shadow_maps_);
    glBindTexture(GL_TEXTURE_2D_ARRAY, shadow_maps_);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, size, size, layers, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    // Read with texelFetch: one level, no comparison.
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    check_gl("the shadow maps");
    shadow_size_ = size, shadow_layers_ = layers;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_);
  glDrawBuffer(GL_NONE), glReadBuffer(GL_NONE);
  glViewport(0, 0, size, size);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST), glDepthFunc(GL_LESS), glDepthMask(GL_TRUE);
  glUseProgram(depth_program_);
  const GLint mvp = uniform(depth_program_, "u_mvp");
  Mat4 flip;
  flip.m[1][1] = -1;
  int layer = 0;
  for (const ShadowLight& l : shadow_lights_)
    for (int f = 0; f < l.faces; ++f, ++layer) {
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, shadow_maps_, 0, layer);
      const float one = 1.0f;
      glClearBufferfv(GL_DEPTH, 0, &one);
      const Mat4 view_projection = flip * l.views[f].projection * l.views[f].view;
      for (const Caster& c : casters_) {
        if (c.two_sided) glDisable(GL_CULL_FACE);
        else glEnable(GL_CULL_FACE), glCullFace(GL_BACK);
        upload_matrix(mvp, view_projection * c.world);
        glBindVertexArray(c.entry->vao);
        glDrawElements(GL_TRIANGLES, GLsizei(c.entry->face_of.size() * 3), GL_UNSIGNED_INT, nullptr);
      }
    }
  glBindVertexArray(0);
  check_gl("the shadow maps");
  // The frame's framebuffer and state (begin_frame's).
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glViewport(0, 0, width_ * ssaa_, height_ * ssaa_);
  glDisable(GL_CULL_FACE);
  if (options_.depth_mode == DepthMode::Painter) glDisable(GL_DEPTH_TEST);
  glActiveTexture(GL_TEXTURE15);
  glBindTexture(GL_TEXTURE_2D_ARRAY, shadow_maps_);
}

// The shadows' uniforms (kLightingGlsl's visibility): which light has which maps, and
// each map's matrix and texel size.
void GpuBackend::upload_shadows(GLuint p) {
  glUniform1i(uniform(p, "u_shadow_maps"), 15);  // (always: unit 0 holds another kind of texture)
  glUniform1i(uniform(p, "u_shadows"), !shadow_lights_.empty());
  if (shadow_lights_.empty()) return;
  std::vector<GLint> directional(lights_.directional.size(), -1), point(lights_.point.size(), -1);
  std::vector<GLint> first, faces;
  std::vector<Vec3> position;
  std::vector<Mat4> eye_to_clip;
  std::vector<Vec2> texel;
  for (const ShadowLight& l : shadow_lights_) {
    (l.directional ? directional : point).at(l.index) = GLint(first.size());
    first.push_back(GLint(eye_to_clip.size())), faces.push_back(l.faces), position.push_back(l.shadow.position);
    for (int f = 0; f < l.faces; ++f) {
      const shading::ShadowMap& m = l.shadow.face[f];
      eye_to_clip.push_back(m.eye_to_clip), texel.push_back({m.texel, m.perspective ? 1.0f : 0.0f});
    }
  }
  if (!directional.empty()) glUniform1iv(uniform(p, "u_directional_shadow"), GLsizei(directional.size()), directional.data());
  if (!point.empty()) glUniform1iv(uniform(p, "u_point_shadow"), GLsizei(point.size()), point.data());
  glUniform1iv(uniform(p, "u_shadow_first"), GLsizei(first.size()), first.data());
  glUniform1iv(uniform(p, "u_shadow_faces"), GLsizei(faces.size()), faces.data());
  glUniform3fv(uniform(p, "u_shadow_position"), GLsizei(position.size()), &position[0].x);
  glUniformMatrix4fv(uniform(p, "u_shadow_eye_to_clip"), GLsizei(eye_to_clip.size()), GL_TRUE, &eye_to_clip[0].m[0][0]);
  glUniform2fv(uniform(p, "u_shadow_texel"), GLsizei(texel.size()), &texel[0].x);
  glUniform1i(uniform(p, "u_shadow_size"), shadow_size_);
}

void GpuBackend::draw(const Mesh& mesh, const Mat4& world, const Material* material, uint32_t object_id) {
  stats_.objects++;
  stats_.triangles += mesh.triangles.size();
  if (mesh.triangles.empty()) return;
  context_->make_current();  // (a no-op unless another renderer's frame ran on this thread since)
  if (options_.shadows) {
    // Every mesh draw casts, seen or not (CpuBackend::draw): both faces for a two-sided material.
    bool two_sided = material ? material->two_sided : mesh.materials.empty() && default_material_.two_sided;
    if (!material)
      for (const Material& mat : mesh.materials) two_sided = two_sided || mat.two_sided;
    casters_.push_back({&mesh_entry(mesh), world, two_sided || !options_.cull_back_faces});
    caster_bounds_ = merge_bounds(caster_bounds_, world_bounds(mesh, world));
  }
  if (geometry::ViewVolume(view_projection_).outside(mesh, world)) return void(stats_.objects_culled++);
  MeshEntry& m = mesh_entry(mesh);
  // Blended (geometry::plan_mesh_draw's d.blend): a slot is Pbr with AlphaMode::Blend.
  bool blend = false;
  const size_t slots = material ? 1 : 1 + mesh.materials.size();
  for (size_t s = 0; s < slots; ++s) {
    const Material& mat = material ? *material : s == 0 ? default_material_ : mesh.materials[s - 1];
    blend = blend || (options_.shading.value_or(mat.shading) == Shading::Pbr && mat.alpha_mode == AlphaMode::Blend);
  }
  // Textures too large for the device: said at the draw that brings them.
  for (size_t s = 0; s < slots; ++s) {
    const Material& mat = material ? *material : s == 0 ? default_material_ : mesh.materials[s - 1];
    for (const Texture* x : {options_.texture ? options_.texture.get() : mat.texture.get(),
                             options_.env_map ? options_.env_map.get() : mat.env_map.get(),
                             mat.pbr.metallic_roughness.texture.get(), mat.pbr.normal.texture.get(),
                             mat.pbr.occlusion.texture.get(), mat.pbr.emissive_map.texture.get()})
      if (x) check_size(*x);
  }
  const float depth = blend ? (view_ * world).transform_point(mesh.bounding_sphere().center).z : 0.0f;
  commands_.push_back({Command::Mesh, uint32_t(mesh_draws_.size())});
  mesh_draws_.push_back({&mesh, &m, world, material, object_id, blend, depth});
}

// Runs the recorded frame (CpuBackend::run_frame's order): the colour pipeline decided
// from every draw's materials (geometry::finish_color_plan), then between each pair of
// clears the opaque draws and batches in order and the blended draws far to near
// (CpuBackend::order_blended_draws); in painter's mode, the batches and clears, then
// every face of the frame sorted (draw_painter).
void GpuBackend::replay() {
  if (options_.shadows && !casters_.empty()) time_pass(kShadowPass), render_shadows();
  time_pass(kOpaquePass);
  bool pbr = false;
  for (const MeshDraw& d : mesh_draws_) {
    const size_t slots = d.material ? 1 : 1 + d.mesh->materials.size();
    for (size_t s = 0; s < slots; ++s) {
      const Material& mat = d.material ? *d.material : s == 0 ? default_material_ : d.mesh->materials[s - 1];
      pbr = pbr || options_.shading.value_or(mat.shading) == Shading::Pbr;
    }
  }
  linear_ = options_.color == ColorPipeline::Linear || (options_.color == ColorPipeline::Auto && pbr);
  const bool painter = options_.depth_mode == DepthMode::Painter;
  std::vector<uint32_t> blended;
  auto flush_blended = [&] {
    if (blended.empty()) return;
    time_pass(kBlendPass);
    std::stable_sort(blended.begin(), blended.end(),
                     [&](uint32_t a, uint32_t b) { return mesh_draws_[a].depth < mesh_draws_[b].depth; });
    for (uint32_t i : blended) {
      const MeshDraw& d = mesh_draws_[i];
      draw_mesh(*d.mesh, *d.entry, d.world, d.material, d.object_id, nullptr);
    }
    blended.clear();
    time_pass(kOpaquePass);
  };
  for (const Command& c : commands_) {
    if (c.kind == Command::Batch) {
      const BatchDraw& b = batch_draws_[c.index];
      draw_batch(b.batch, b.state, b.primitives);
    } else if (c.kind == Command::Clear) {
      flush_blended();
      run_clear(clears_[c.index]);
    } else if (!painter) {
      const MeshDraw& d = mesh_draws_[c.index];
      if (d.blend) blended.push_back(c.index);
      else draw_mesh(*d.mesh, *d.entry, d.world, d.material, d.object_id, nullptr);
    }
  }
  flush_blended();
  if (painter && !mesh_draws_.empty()) time_pass(kBlendPass), draw_painter();
  time_pass(-1);
}

// Ends the query of the pass being timed and starts one for `pass` (-1: none).
void GpuBackend::time_pass(int pass) {
  if (pass == timing_) return;
  if (timing_ >= 0) glEndQuery(GL_TIME_ELAPSED);
  timing_ = pass;
  if (pass < 0) return;
  GLuint q = 0;
  if (spare_queries_.empty()) glGenQueries(1, &q);
  else q = spare_queries_.back(), spare_queries_.pop_back();
  glBeginQuery(GL_TIME_ELAPSED, q);
  queries_.push_back({pass, q});
}

// The frame's queries into stats_ when `read` (the frame finished), else dropped (it
// failed); their objects kept for the next frame.
void GpuBackend::end_timing(bool read) {
  time_pass(-1);
  double* totals[] = {&stats_.gpu_shadow_ms, &stats_.gpu_opaque_ms, &stats_.gpu_blend_ms};
  for (const auto& [pass, q] : queries_) {
    GLuint64 ns = 0;
    if (read) glGetQueryObjectui64v(q, GL_QUERY_RESULT, &ns);
    *totals[pass] += double(ns) * 1e-6;
    spare_queries_.push_back(q);
  }
  queries_.clear();
}

// The output's uniforms (kColorGlsl's finish): 0 display, 1 Linear's whole transform,
// 2 the sRGB encoding alone.
void GpuBackend::set_output(GLuint p, int output) {
  glUniform1i(uniform(p, "u_output"), output);
  const float e = options_.exposure;
  glUniform1f(uniform(p, "u_exposure"), std::isfinite(e) && e >= 0 ? e : 1.0f);  // (as CpuBackend::run_frame)
  glUniform1i(uniform(p, "u_tone_map"), int(options_.tone_map));
}

// Tangents for a normal-mapped Pbr material: the mesh's, else generated as the CPU
// generates them (geometry::generate_tangents, from the material's uv set), once per
// uv set asked for.
void GpuBackend::ensure_tangents(const Mesh& mesh, MeshEntry& m, int uv_set) {
  if (m.tangent_uv_set == 2 || m.tangent_uv_set == uv_set) return;
  const size_t nv = mesh.positions.size();
  std::vector<Vec3> averaged;
  const std::vector<Vec3>* normals = &mesh.normals;
  if (mesh.normals.size() != nv) geometry::average_normals(mesh, averaged), normals = &averaged;
  const std::vector<Vec2>& uvs = uv_set == 1 && !mesh.uvs1.empty() ? mesh.uvs1 : mesh.uvs;
  std::vector<Vec4> tangents;
  geometry::generate_tangents(mesh, *normals, uvs.empty() ? std::vector<Vec2>(nv) : uvs, tangents);
  glBindVertexArray(m.vao);
  glBindBuffer(GL_ARRAY_BUFFER, m.buffers[7]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(tangents.size() * sizeof(Vec4)), tangents.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(5, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(5);
  if (m.tangent_uv_set < 0) {
    reserve(tangents.size() * sizeof(Vec4), "mesh '" + mesh.name + "' (its tangents)");
    m.bytes += tangents.size() * sizeof(Vec4), cache_bytes_ += tangents.size() * sizeof(Vec4);
  }
  m.tangent_uv_set = uv_set;
  check_gl(("generating tangents for mesh '" + mesh.name + "'").c_str());
}

// A Pbr slot's uniforms and textures (geometry::plan_pbr and finish_color_plan).
void GpuBackend::draw_pbr_slot(const Mesh& mesh, MeshEntry& m, const Material& mat, GLuint p) {
  const PbrParams& pbr = mat.pbr;
  const int uv_set = pbr_uv_set(mat);
  const bool tangents = bool(pbr.normal) && !pbr.unlit;
  if (tangents) ensure_tangents(mesh, m, uv_set == 1 && !mesh.uvs1.empty() ? 1 : 0);
  glBindVertexArray(m.vao);
  if (!m.has_uvs1) glVertexAttrib2f(4, 0, 0);
  if (m.tangent_uv_set < 0) glVertexAttrib4f(5, 1, 0, 0, 1);
  if (!m.has_alphas) glVertexAttrib1f(6, 1);
  glUniform1i(uniform(p, "u_uv1"), uv_set == 1 && m.has_uvs1);
  glUniform1i(uniform(p, "u_vertex_colors"), m.has_colors);
  glUniform1i(uniform(p, "u_color_convert"), color_convert(mat.color_space, linear_));
  glUniform1i(uniform(p, "u_tangents"), tangents);
  const Vec3 base = geometry::pipeline_color(mat.color, mat.color_space, linear_);
  const Vec3 emissive = geometry::pipeline_color(pbr.emissive, mat.color_space, linear_);
  glUniform4f(uniform(p, "u_base"), base.x, base.y, base.z, mat.alpha);
  glUniform3f(uniform(p, "u_emissive"), emissive.x, emissive.y, emissive.z);
  glUniform4f(uniform(p, "u_pbr"), pbr.metallic, pbr.roughness, pbr.normal_scale, pbr.occlusion_strength);
  glUniform1i(uniform(p, "u_unlit"), pbr.unlit);
  glUniform1i(uniform(p, "u_alpha_mode"), int(mat.alpha_mode));
  glUniform1f(uniform(p, "u_alpha_cutoff"), mat.alpha_cutoff);
  glUniform1i(uniform(p, "u_ortho"), orthographic_);
  glUniform1i(uniform(p, "u_two_sided"), mat.two_sided);
  set_output(p, linear_ ? 1 : 0);
  // The five textures on units 4..8: base colour and emissive are colours (sRGB-decoded
  // in a Linear frame), the others data.
  const Texture* base_map = options_.texture ? options_.texture.get() : mat.texture.get();
  const Filter filter = options_.filter.value_or(mat.filter);
  struct Map {
    const char* name;
    const Texture* texture;
    const UvTransform& uv;
    bool color;
  };
  const Map maps[5] = {{"u_base_map", base_map, mat.texture_uv, true},
                       {"u_mr_map", pbr.metallic_roughness.texture.get(), pbr.metallic_roughness.uv, false},
                       {"u_normal_map", pbr.normal.texture.get(), pbr.normal.uv, false},
                       {"u_occlusion_map", pbr.occlusion.texture.get(), pbr.occlusion.uv, false},
                       {"u_emissive_map", pbr.emissive_map.texture.get(), pbr.emissive_map.uv, true}};
  GLint has[5];
  float rows[30];
  for (int i = 0; i < 5; ++i) {
    const Map& map = maps[i];
    has[i] = map.texture != nullptr;
    glUniform1i(uniform(p, map.name), 4 + i);
    uv_map_rows(map.uv, rows + 6 * i);
    if (!map.texture) continue;
    glActiveTexture(GLenum(GL_TEXTURE4 + i));
    glBindTexture(GL_TEXTURE_2D, texture(*map.texture, map.color && linear_));
    glBindSampler(GLuint(4 + i), sampler(filter, mat.wrap));
  }
  glUniform1iv(uniform(p, "u_has_map"), 5, has);
  glUniform3fv(uniform(p, "u_map_uv"), 10, rows);
  // BLEND: over, in the output's encoding (pbr_kernel's mix; alpha: a + dst (1 - a)),
  // without writing depth.
  if (mat.alpha_mode == AlphaMode::Blend) {
    glEnablei(GL_BLEND, 0);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glBlendEquation(GL_FUNC_ADD);
    glDepthMask(GL_FALSE);
  }
}

// One mesh draw, every material slot; `faces`, in painter's mode, the sorted runs of
// this draw's faces to draw instead of all (first: position in the frame's order, count).
void GpuBackend::draw_mesh(const Mesh& mesh, MeshEntry& m, const Mat4& world, const Material* override,
                           uint32_t object_id, const std::vector<std::pair<uint32_t, uint32_t>>* runs) {
  const Mat4 model_view = view_ * world;
  const Mat4 mvp = flipped_view_projection_ * world, normals = normal_matrix(model_view);
  glBindVertexArray(m.vao);
  if (!m.has_uvs) glVertexAttrib2f(2, 0, 0);
  if (!m.has_colors) glVertexAttrib3f(3, 0, 0, 0);
  if (runs) glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, painter_indices_);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_BUFFER, m.face_colors);
  glActiveTexture(GL_TEXTURE3);
  glBindTexture(GL_TEXTURE_BUFFER, order_texture_);

  const size_t slots = m.slot_begin.size() - 1;
  for (size_t slot = 0; slot < slots; ++slot) {
    const uint32_t begin = m.slot_begin[slot], end = m.slot_begin[slot + 1];
    if (begin == end) continue;
    // The material as plan_mesh_draw reads it (geometry/draw_plan.cpp).
    const Material& mat = override ? *override : slot == 0 ? default_material_ : mesh.materials[slot - 1];
    const Shading shading = options_.shading.value_or(mat.shading);
    const Texture* tex = options_.texture ? options_.texture.get() : mat.texture.get();
    const Texture* env = options_.env_map ? options_.env_map.get() : mat.env_map.get();
    const Filter filter = options_.filter.value_or(mat.filter);
    const bool lines = shading == Shading::Wireframe, points = shading == Shading::Points;
    const bool replace = tex && mat.texture_mode == TextureMode::Replace && !lines && !points;
    const bool pbr = shading == Shading::Pbr;
    const bool phong = !replace && shading == Shading::Phong;
    const int mode = replace || lines || points ? kSolid : shading == Shading::Flat ? kFlat : phong ? kPhong : kSmooth;
    const bool lit = shading != Shading::Unlit;
    const bool uv_from_env = !phong && !tex && env && !lines && !points;
    const bool textured = !lines && !points && (tex || uv_from_env);
    const bool cull = options_.cull_back_faces && !mat.two_sided;
    int base = kMaterialColor;
    if (!override && !mesh.face_colors.empty()) base = kFaceColor;
    else if (!override && !mesh.colors.empty()) base = kVertexColor;
    // Colours in the frame's pipeline (mesh_job.cpp's base_color); lines and points in
    // display values (finish_color_plan's line_color).
    Vec3 color = replace ? Vec3{1, 1, 1} : geometry::pipeline_color(mat.color, mat.color_space, linear_);
    if (lines || points) color = geometry::pipeline_color(mat.color, mat.color_space, false);

    const bool direct = (mode == kSmooth || mode == kPhong) && base != kFaceColor;
    const int primitive = pbr ? 3 : lines ? 1 : points ? 2 : direct ? 3 : 0;
    const GLuint p = pbr ? pbr_program(options_.affine) : program(options_.affine, primitive);
    glUseProgram(p);
    const int which = pbr ? 8 + options_.affine : (options_.affine ? 4 : 0) + primitive;
    if (!lights_uploaded_[which]) upload_lights(p), lights_uploaded_[which] = true;
    upload_matrix(uniform(p, "u_mvp"), mvp);
    upload_matrix(uniform(p, "u_model_view"), model_view);
    upload_matrix(uniform(p, "u_normal_matrix"), normals);
    glUniform1ui(uniform(p, "u_object_id"), object_id);
    if (pbr) {
      draw_pbr_slot(mesh, m, mat, p);
    } else {
      glUniform1i(uniform(p, "u_texture"), 0), glUniform1i(uniform(p, "u_env_map"), 1);
      glUniform1i(uniform(p, "u_face_colors"), 2), glUniform1i(uniform(p, "u_order"), 3);
      glUniform1i(uniform(p, "u_face_order"), runs ? 1 : 0);
      glUniform1i(uniform(p, "u_mode"), mode);
      glUniform1i(uniform(p, "u_base_source"), base);
      glUniform1i(uniform(p, "u_lit"), lit);
      glUniform1i(uniform(p, "u_vertex_light"), mode == kSmooth && lit);
      glUniform1i(uniform(p, "u_unlit_vertex_colors"), shading == Shading::Unlit && !mesh.colors.empty() && mode == kSmooth);
      glUniform1i(uniform(p, "u_uv_from_env"), uv_from_env);
      glUniform1i(uniform(p, "u_two_sided"), mat.two_sided);
      glUniform1i(uniform(p, "u_cull"), cull);
      if (points) {
        // mesh_job.cpp's point_size(): 1..64, times the super-sampling factor.
        const float size = std::isfinite(options_.point_size) ? std::clamp(options_.point_size, 1.0f, 64.0f) : 1.0f;
        glUniform1f(uniform(p, "u_point_size"), float(std::max(1, int(size * float(ssaa_) + 0.5f))));
        glEnable(GL_PROGRAM_POINT_SIZE);
      }
      if (lines) {  // (the edges map their ends to window pixels themselves)
        glUniform4f(uniform(p, "u_viewport"), 0, 0, float(width_ * ssaa_), float(height_ * ssaa_));
        glUniform2f(uniform(p, "u_depth_range"), 0, 1);
      }
      glUniform1i(uniform(p, "u_textured"), textured);
      glUniform1i(uniform(p, "u_env"), phong && env);
      glUniform1f(uniform(p, "u_env_mix"), mat.env_mix);
      glUniform3f(uniform(p, "u_material_color"), color.x, color.y, color.z);
      glUniform1i(uniform(p, "u_color_convert"), color_convert(mat.color_space, linear_));
      // The flat kernel writes its colour encoded but not exposed or tone mapped
      // (mesh_job.cpp's pack_flat); lines and points are display values.
      set_output(p, lines || points ? 0 : mode == kFlat && !textured ? (linear_ ? 2 : 0) : (linear_ ? 1 : 0));
      const shading::Specular s(mat.specular, mat.shininess);
      glUniform3f(uniform(p, "u_specular"), s.ks, s.exponent, s.cutoff);
      if (textured) {
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, texture(tex ? *tex : *env, linear_));
        glBindSampler(0, sampler(filter, tex ? mat.wrap : Wrap::Clamp));  // environment maps: clamped
      }
      if (phong && env) {
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, texture(*env, linear_));
        glBindSampler(1, sampler(filter, Wrap::Clamp));
      }
    }
    // Triangles are culled by GL (front faces clockwise: the flip); edges and corners
    // by the geometry shader.
    if (cull && (primitive == 0 || primitive == 3)) glEnable(GL_CULL_FACE), glCullFace(GL_BACK);
    else glDisable(GL_CULL_FACE);
    if (!runs) {
      glUniform1i(uniform(p, "u_face_base"), GLint(begin));
      glDrawElements(GL_TRIANGLES, GLsizei(end - begin) * 3, GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(uintptr_t(begin) * 12));
    } else {
      for (const auto& [first, count] : *runs) {
        // A run is one slot's faces (the sort keeps slots apart): draw it with its slot.
        const uint32_t face = painter_faces_[first];
        if (face < begin || face >= end) continue;
        glUniform1i(uniform(p, "u_face_base"), GLint(first));
        glDrawElements(GL_TRIANGLES, GLsizei(count) * 3, GL_UNSIGNED_INT, reinterpret_cast<const void*>(uintptr_t(first) * 12));
      }
    }
    if (pbr && mat.alpha_mode == AlphaMode::Blend) glDisablei(GL_BLEND, 0), glDepthMask(GL_TRUE);
  }
  if (runs) glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.buffers[4]);  // the VAO's own again
  glBindVertexArray(0);
  stats_.triangles_rasterized += runs ? 0 : m.face_of.size();
}

// Painter's mode (raster/bins.cpp's bin_deferred): every face of the frame sorted by the
// mean window depth of its corners, far to near, ties in submission order; drawn in
// that order with the depth test off, in runs of one draw and material slot.
void GpuBackend::draw_painter() {
  struct Key {
    float depth;
    uint32_t draw, face;  // face: in the entry's slot order
  };
  std::vector<Key> keys;
  for (uint32_t d = 0; d < mesh_draws_.size(); ++d) {
    const MeshDraw& pd = mesh_draws_[d];
    const Mesh& mesh = *pd.mesh;
    const Mat4 mvp = view_projection_ * pd.world;
    std::vector<float> z(mesh.positions.size());
    for (size_t v = 0; v < z.size(); ++v) {
      const Vec3 q = mesh.positions[v];
      const Vec4 c = mvp * Vec4{q.x, q.y, q.z, 1.0f};
      z[v] = c.w != 0 ? 0.5f * (c.z / c.w) + 0.5f : 1.0f;
    }
    for (uint32_t i = 0; i < pd.entry->face_of.size(); ++i) {
      const Triangle& t = mesh.triangles[pd.entry->face_of[i]];
      keys.push_back({(z[t.v[0]] + z[t.v[1]] + z[t.v[2]]) / 3.0f, d, i});
    }
  }
  std::stable_sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) { return a.depth > b.depth; });
  // The frame's order: indices (3 a face) and, per position, the face in its entry.
  std::vector<uint32_t> indices(keys.size() * 3);
  painter_faces_.resize(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    const MeshDraw& pd = mesh_draws_[keys[i].draw];
    const Triangle& t = pd.mesh->triangles[pd.entry->face_of[keys[i].face]];
    for (int k = 0; k < 3; ++k) indices[i * 3 + size_t(k)] = t.v[k] < pd.mesh->positions.size() ? t.v[k] : 0;
    painter_faces_[i] = keys[i].face;
  }
  if (!painter_indices_) glGenBuffers(1, &painter_indices_), glGenBuffers(1, &order_buffer_), glGenTextures(1, &order_texture_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, painter_indices_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(indices.size() * 4), indices.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_TEXTURE_BUFFER, order_buffer_);
  glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(painter_faces_.size() * 4), painter_faces_.data(), GL_STREAM_DRAW);
  glBindTexture(GL_TEXTURE_BUFFER, order_texture_);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_R32I, order_buffer_);
  // Runs of consecutive faces of one draw and one slot, each drawn by its draw in order.
  size_t i = 0;
  while (i < keys.size()) {
    const uint32_t d = keys[i].draw;
    MeshEntry& m = *mesh_draws_[d].entry;
    auto slot = [&](uint32_t f) { return std::upper_bound(m.slot_begin.begin(), m.slot_begin.end(), f) - m.slot_begin.begin(); };
    size_t j = i + 1;
    while (j < keys.size() && keys[j].draw == d && slot(keys[j].face) == slot(keys[i].face)) ++j;
    const std::vector<std::pair<uint32_t, uint32_t>> run = {{uint32_t(i), uint32_t(j - i)}};
    const MeshDraw& pd = mesh_draws_[d];
    draw_mesh(*pd.mesh, m, pd.world, pd.material, pd.object_id, &run);
    i = j;
  }
  for (const MeshDraw& pd : mesh_draws_) stats_.triangles_rasterized += pd.entry->face_of.size();
}

namespace {

GLenum gl_compare(CompareFunc f) { return GL_NEVER + GLenum(f); }  // the same order as GL's enums

GLenum gl_stencil_op(StencilOp op) {
  switch (op) {
    case StencilOp::Keep: return GL_KEEP;
    case StencilOp::Zero: return GL_ZERO;
    case StencilOp::Replace: return GL_REPLACE;
    case StencilOp::Increment: return GL_INCR;
    case StencilOp::Decrement: return GL_DECR;
    case StencilOp::Invert: return GL_INVERT;
    case StencilOp::IncrementWrap: return GL_INCR_WRAP;
    case StencilOp::DecrementWrap: return GL_DECR_WRAP;
  }
  return GL_KEEP;
}

GLenum gl_factor(BlendFactor f) {
  static const GLenum table[] = {GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR,
                                 GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA,
                                 GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA_SATURATE, GL_CONSTANT_COLOR,
                                 GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA};
  return table[size_t(f)];
}

GLenum gl_blend_op(BlendOp op) {
  static const GLenum table[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
  return table[size_t(op)];
}

// GL_CLAMP (Wrap::ClampHalfBorder) has no core-profile sampler mode: clamped to the
// edge, exact for GL_NEAREST; with GL_LINEAR the last half texel does not blend in the
// border colour as the CPU backend's does (docs/gpu.md).
GLint gl_wrap(Wrap w) {
  return w == Wrap::Repeat                                 ? GL_REPEAT
         : w == Wrap::Clamp || w == Wrap::ClampHalfBorder ? GL_CLAMP_TO_EDGE
         : w == Wrap::MirroredRepeat                       ? GL_MIRRORED_REPEAT
                                                           : GL_CLAMP_TO_BORDER;
}

}  // namespace

// A batch of pre-transformed primitives (pGL's path), drawn at once in submission order
// (painter's mode does not sort them). Vertex arrays are streamed per draw.
void GpuBackend::draw(const PrimitiveBatch& batch, const PixelState& state, uint32_t primitives) {
  if (batch.clip_planes > kMaxUserClipPlanes)
    throw Error("a primitive batch has " + std::to_string(batch.clip_planes) + " user clip planes (at most " +
                std::to_string(kMaxUserClipPlanes) + ")");
  if (batch.clip_planes && !batch.clip_distance) throw Error("a primitive batch has user clip planes but no clip distances");
  if (state.logic_op) throw Error("the GPU backend does not apply glLogicOp yet");
  if (state.polygon_stipple) throw Error("the GPU backend does not apply glPolygonStipple yet");
  if (state.samples_passed) throw Error("the GPU backend does not count samples (occlusion queries) yet");
  if (state.color_sum) throw Error("the GPU backend does not add a secondary colour (GL_COLOR_SUM) yet");
  if (state.texture.texture && state.texture1.texture)
    throw Error("the GPU backend does not apply a second texture unit yet");
  if (state.texture.texture && state.texture.env == TexEnvMode::Combine)
    throw Error("the GPU backend does not apply the GL_COMBINE texture environment yet");
  {
    const SamplerState& ss = state.texture.sampler;
    if (state.texture.texture && (ss.lod_bias != 0 || ss.min_lod > -1000 || ss.max_lod < 1000))
      throw Error("the GPU backend does not apply the texture's level-of-detail bias or clamp yet");
    if (state.texture.texture && state.texture.texture->volume()) throw Error("the GPU backend does not sample 3-D textures yet");
    if (state.texture.texture && state.texture.texture->levels()[0].border)
      throw Error("the GPU backend does not sample texture borders yet");
  }
  stats_.objects++;
  if (primitives == 0) return;
  commands_.push_back({Command::Batch, uint32_t(batch_draws_.size())});
  batch_draws_.push_back({batch, state, primitives});
}

void GpuBackend::draw_batch(const PrimitiveBatch& batch, const PixelState& state, uint32_t primitives) {
  const uint32_t k = batch.kind == PrimitiveKind::Triangles ? 3 : batch.kind == PrimitiveKind::Lines ? 2 : 1;
  // The vertices of whole primitives whose indices are all in range (the rest are dropped).
  batch_indices_.clear();
  for (uint32_t p = 0; p < primitives; ++p) {
    uint32_t v[3];
    bool ok = true;
    for (uint32_t i = 0; i < k; ++i) {
      v[i] = batch.indices ? batch.indices[p * k + i] : p * k + i;
      ok = ok && v[i] < batch.vertex_count;
    }
    if (ok) batch_indices_.insert(batch_indices_.end(), v, v + k);
  }
  if (batch_indices_.empty()) return;
  if (k == 3) stats_.triangles += batch_indices_.size() / 3, stats_.triangles_rasterized += batch_indices_.size() / 3;
  else if (k == 2) stats_.lines += batch_indices_.size() / 2;
  else stats_.points += batch_indices_.size();

  if (!batch_vao_) glGenVertexArrays(1, &batch_vao_), glGenBuffers(6, batch_buffers_);
  GLuint& p = batch_programs_[k == 2];
  if (!p) p = build_batch_program(k == 2);
  glUseProgram(p);
  glBindVertexArray(batch_vao_);
  const size_t n = batch.vertex_count;
  auto stream = [&](GLuint index, const void* data, size_t bytes, int components, std::initializer_list<float> constant) {
    if (!data) {
      glDisableVertexAttribArray(index);
      const float* c = constant.begin();
      glVertexAttrib4f(index, c[0], c[1], c[2], c[3]);
      return;
    }
    glBindBuffer(GL_ARRAY_BUFFER, batch_buffers_[index]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(bytes), data, GL_STREAM_DRAW);
    glVertexAttribPointer(index, components, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(index);
  };
  stream(0, batch.position, n * sizeof(Vec4), 4, {0, 0, 0, 1});
  stream(1, batch.color, n * sizeof(Vec4), 4, {1, 1, 1, 1});
  stream(2, batch.texcoord, n * sizeof(Vec4), 4, {0, 0, 0, 1});
  stream(3, batch.fog, n * sizeof(float), 1, {0, 0, 0, 1});
  // User clip planes: each vertex's distances, the first four and the other two as two
  // attributes of one buffer, written to gl_ClipDistance (GL clips where one is < 0,
  // interpolated linearly in clip space, as the CPU's clipper does).
  const uint32_t planes = batch.clip_planes;
  if (planes) {
    const GLsizei stride = GLsizei(planes * sizeof(float));
    glBindBuffer(GL_ARRAY_BUFFER, batch_buffers_[5]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(n * planes * sizeof(float)), batch.clip_distance, GL_STREAM_DRAW);
    glVertexAttribPointer(4, GLint(std::min(planes, 4u)), GL_FLOAT, GL_FALSE, stride, nullptr);
    glEnableVertexAttribArray(4);
    if (planes > 4) {
      glVertexAttribPointer(5, GLint(planes - 4), GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(16));
      glEnableVertexAttribArray(5);
    } else {
      glDisableVertexAttribArray(5);
    }
  } else {
    glDisableVertexAttribArray(4), glDisableVertexAttribArray(5);
  }
  for (uint32_t c = 0; c < kMaxUserClipPlanes; ++c)
    c < planes ? glEnable(GLenum(GL_CLIP_DISTANCE0 + c)) : glDisable(GLenum(GL_CLIP_DISTANCE0 + c));
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, batch_buffers_[4]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(batch_indices_.size() * 4), batch_indices_.data(), GL_STREAM_DRAW);

  // The viewport (rows from the top: the framebuffer is upside down, so GL's rows are
  // the image's) and depth range, as plan_batch_draw bounds them.
  const int fw = width_ * ssaa_, fh = height_ * ssaa_;
  const Viewport& v = batch.viewport;
  const int vw = v.width > 0 ? std::min(v.width, kMaxFramebufferSide) : fw;
  const int vh = v.height > 0 ? std::min(v.height, kMaxFramebufferSide) : fh;
  const int vx = v.width > 0 ? std::clamp(v.x, -kMaxFramebufferSide, kMaxFramebufferSide) : 0;
  const int vy = v.height > 0 ? std::clamp(v.y, -kMaxFramebufferSide, kMaxFramebufferSide) : 0;
  glViewport(vx, vy, vw, vh);
  const float near = std::clamp(v.depth_near, 0.0f, 1.0f), far = std::clamp(v.depth_far, 0.0f, 1.0f);
  glDepthRange(near, far);
  if (k == 2) {  // the line program maps its ends to window pixels itself
    glUniform4f(uniform(p, "u_viewport"), float(vx), float(vy), float(vw), float(vh));
    glUniform2f(uniform(p, "u_depth_range"), near, far);
    const float width = std::floor(batch.line_width + 0.5f);  // (as batch_job.cpp rounds it; NaN: 1)
    glUniform1f(uniform(p, "u_line_width"), width >= 1.0f ? std::min(width, 255.0f) : 1.0f);
    glUniform1i(uniform(p, "u_clip_planes"), GLint(planes));
  }

  const TextureStage& t = state.texture;
  glUniform1i(uniform(p, "u_textured"), t.texture != nullptr);
  if (t.texture) {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture(*t.texture));
    const SamplerState& ss = t.sampler;
    GLuint& sampler = batch_samplers_[{int(ss.mag), int(ss.min), int(ss.mip), int(ss.wrap_s), int(ss.wrap_t),
                                       ss.border_color.x, ss.border_color.y, ss.border_color.z, ss.border_color.w}];
    if (!sampler) {
      glGenSamplers(1, &sampler);
      const bool linear = ss.min == SamplerState::Texel::Linear;
      const GLint min = ss.mip == SamplerState::Mip::None ? (linear ? GL_LINEAR : GL_NEAREST)
                        : ss.mip == SamplerState::Mip::Nearest ? (linear ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST)
                                                               : (linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR);
      glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, min);
      glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, ss.mag == SamplerState::Texel::Linear ? GL_LINEAR : GL_NEAREST);
      glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, gl_wrap(ss.wrap_s));
      glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, gl_wrap(ss.wrap_t));
      glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, &ss.border_color.x);
    }
    glBindSampler(0, sampler);
    glUniform1i(uniform(p, "u_texture"), 0);
    glUniform1i(uniform(p, "u_format"), int(t.format));
    glUniform1i(uniform(p, "u_env"), int(t.env));
    glUniform4fv(uniform(p, "u_env_color"), 1, &t.env_color.x);
  }
  glUniform1i(uniform(p, "u_fog"), state.fog);
  glUniform1i(uniform(p, "u_fog_mode"), int(state.fog_mode));
  glUniform3f(uniform(p, "u_fog_params"), state.fog_start, state.fog_end, state.fog_density);
  glUniform4fv(uniform(p, "u_fog_color"), 1, &state.fog_color.x);
  glUniform1i(uniform(p, "u_alpha_test"), state.alpha_test);
  glUniform1i(uniform(p, "u_alpha_func"), int(state.alpha_func));
  glUniform1f(uniform(p, "u_alpha_ref"), state.alpha_ref);
  glUniform1i(uniform(p, "u_offset"), state.polygon_offset);
  glUniform2f(uniform(p, "u_offset_params"), state.offset_factor, state.offset_units);
  glUniform1f(uniform(p, "u_point_size"), std::max(batch.point_size, 1.0f));

  // GL's own per-fragment state: scissor, depth, blend, masks.
  if (state.scissor) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(state.scissor_x0, state.scissor_y0, std::max(state.scissor_x1 - state.scissor_x0, 0),
              std::max(state.scissor_y1 - state.scissor_y0, 0));
  } else {
    glDisable(GL_SCISSOR_TEST);
  }
  const bool painter = options_.depth_mode == DepthMode::Painter;
  if (state.depth_test && !painter) glEnable(GL_DEPTH_TEST), glDepthFunc(gl_compare(state.depth_func));
  else glDisable(GL_DEPTH_TEST);
  glDepthMask(state.depth_write);
  if (state.blend) {
    glEnablei(GL_BLEND, 0);
    glBlendFuncSeparate(gl_factor(state.blend_src_rgb), gl_factor(state.blend_dst_rgb), gl_factor(state.blend_src_alpha),
                        gl_factor(state.blend_dst_alpha));
    glBlendEquation(gl_blend_op(state.blend_op));
    glBlendColor(state.blend_color.x, state.blend_color.y, state.blend_color.z, state.blend_color.w);
  } else {
    glDisablei(GL_BLEND, 0);
  }
  // The stencil test (PixelState: the same test and operations as GL's).
  if (state.stencil_test) {
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(gl_compare(state.stencil_func), state.stencil_ref, state.stencil_value_mask);
    glStencilOp(gl_stencil_op(state.stencil_fail), gl_stencil_op(state.stencil_depth_fail), gl_stencil_op(state.stencil_pass));
    glStencilMask(state.stencil_write_mask);
    stencil_used_ = true;
  } else {
    glDisable(GL_STENCIL_TEST);
  }
  const uint8_t m = state.color_mask;
  glColorMaski(0, m & 1, (m >> 1) & 1, (m >> 2) & 1, (m >> 3) & 1);
  glColorMaski(1, m != 0, GL_FALSE, GL_FALSE, GL_FALSE);  // the id goes with the colour
  glDisable(GL_CULL_FACE);
  glEnable(GL_PROGRAM_POINT_SIZE);
  const GLenum mode = k == 3 ? GL_TRIANGLES : k == 2 ? GL_LINES : GL_POINTS;
  glDrawElements(mode, GLsizei(batch_indices_.size()), GL_UNSIGNED_INT, nullptr);

  // Back to the mesh draws' state.
  glViewport(0, 0, fw, fh);
  glDepthRange(0, 1);
  glDisable(GL_SCISSOR_TEST);
  glDisablei(GL_BLEND, 0);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE), glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  if (painter) glDisable(GL_DEPTH_TEST);
  else glEnable(GL_DEPTH_TEST), glDepthFunc(GL_LESS);
  glDisable(GL_STENCIL_TEST), glStencilMask(0xff);
  for (uint32_t c = 0; c < planes; ++c) glDisable(GLenum(GL_CLIP_DISTANCE0 + c));
  glBindVertexArray(0);
}

void GpuBackend::clear(const ClearRequest& request) {
  commands_.push_back({Command::Clear, uint32_t(clears_.size())});
  clears_.push_back(request);
}

void GpuBackend::run_clear(const ClearRequest& request) {
  if (request.scissor) {
    glEnable(GL_SCISSOR_TEST);  // (rows from the top: the framebuffer is upside down)
    glScissor(request.x0, request.y0, std::max(request.x1 - request.x0, 0), std::max(request.y1 - request.y0, 0));
  }
  if (request.color) {
    const uint8_t k = request.color_mask;
    glColorMask(k & 1, (k >> 1) & 1, (k >> 2) & 1, (k >> 3) & 1);
    const float c[4] = {request.color_value.x, request.color_value.y, request.color_value.z, request.color_value.w};
    glClearBufferfv(GL_COLOR, 0, c);
    const GLuint zero[4] = {0, 0, 0, 0};
    glClearBufferuiv(GL_COLOR, 1, zero);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  if (request.depth && request.depth_write) {
    const float d = std::clamp(request.depth_value, 0.0f, 1.0f);
    glClearBufferfv(GL_DEPTH, 0, &d);
  }
  if (request.stencil) {
    const GLint value = request.stencil_value;
    glStencilMask(request.stencil_mask);
    glClearBufferiv(GL_STENCIL, 0, &value);
    glStencilMask(0xff);
    stencil_used_ = true;
  }
  glDisable(GL_SCISSOR_TEST);
}

const FrameStats& GpuBackend::end_frame() {
  context_->make_current();
  try {
    const auto t_submit = std::chrono::steady_clock::now();
    const double uploads_before = stats_.upload_ms;
    replay();
    stats_.submit_ms = ms_since(t_submit) - (stats_.upload_ms - uploads_before);
    const auto t_wait = std::chrono::steady_clock::now();
    glFinish();
    stats_.gpu_wait_ms = ms_since(t_wait);
    end_timing(true);
    check_gl("the GPU frame");
    context_->check_lost("the GPU frame");
  } catch (...) {
    end_timing(false);
    context_->release();
    throw;
  }
  // Nothing is read back yet: each read below fetches what it needs, once a frame.
  {
    std::lock_guard<std::mutex> lock(fetch_mutex_);
    // (A stencil not fetched last frame is still the GPU's alone.)
    pending_ = kColor | kDepth | (options_.object_ids ? kIds : 0u) | ((stencil_used_ || (pending_ & kStencil)) ? kStencil : 0u);
    stencil_used_ = false;
    samples_.keep_ids(options_.object_ids);
    stats_.readback_ms = reads_ms_, reads_ms_ = 0;  // the last frame's reads (FrameStats)
    stats_.gpu_read_ms = gpu_reads_ms_, gpu_reads_ms_ = 0;
  }
  std::fill(samples_.tile_clean.begin(), samples_.tile_clean.end(), 0);
  evict();
  context_->release();
  stats_.tile_ms = ms_since(t0_);
  return stats_;
}

// Reads the planes in `what` (of the last frame, those not read yet) into the CPU
// framebuffer's samples, where the CPU pipeline's own read-backs take them.
void GpuBackend::fetch(unsigned what) const {
  std::lock_guard<std::mutex> lock(fetch_mutex_);
  what &= pending_;
  if (!what) return;
  const auto t0 = std::chrono::steady_clock::now();
  const int w = width_ * ssaa_, h = height_ * ssaa_;
  Current current(*context_);
  GpuTimer gpu_time(read_query_, gpu_reads_ms_);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  if (what & kColor) {
    rows_.resize(size_t(w) * size_t(h));
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rows_.data());
    scatter(rows_.data(), samples_.color.data());
  }
  if (what & kDepth) {
    depth_rows_.resize(size_t(w) * size_t(h));
    glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth_rows_.data());
    scatter(depth_rows_.data(), samples_.depth.data());
  }
  if (what & kStencil) {
    stencil_rows_.resize(size_t(w) * size_t(h));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil_rows_.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    scatter(stencil_rows_.data(), samples_.stencil.data());
  }
  if (what & kIds) {
    rows_.resize(size_t(w) * size_t(h));
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    glReadPixels(0, 0, w, h, GL_RED_INTEGER, GL_UNSIGNED_INT, rows_.data());
    scatter(rows_.data(), samples_.ids.data());
  }
  check_gl("reading the GPU frame back");
  pending_ &= ~what;
  reads_ms_ += ms_since(t0);
}

// Rows (row 0 first) into the framebuffer's 64x64 tiles of 4x4 blocks, a band of tile
// rows to each of the renderer's threads (memory-bound: one thread cannot keep up).
template <class T>
void GpuBackend::scatter(const T* rows, T* tiled) const {
  const int w = samples_.width, h = samples_.height;
  constexpr int kBand = 64;
  pool().run((h + kBand - 1) / kBand, [&](int band) {
    for (int y = band * kBand; y < std::min(h, (band + 1) * kBand); ++y) {
      const T* row = rows + size_t(y) * size_t(w);
      int x = 0;
      for (; x + 4 <= w; x += 4) std::memcpy(tiled + samples_.index(x, y), row + x, 4 * sizeof(T));
      for (; x < w; ++x) tiled[samples_.index(x, y)] = row[x];
    }
  });
}

// Drops what was not used for a while, and the least recently used beyond the budget.
void GpuBackend::evict() {
  for (auto it = meshes_.begin(); it != meshes_.end();) {
    if (frame_ - it->second.last_frame > kEvictFrames || (cache_bytes_ > budget_ && it->second.last_frame != frame_)) {
      cache_bytes_ -= it->second.bytes;
      free(it->second);
      it = meshes_.erase(it);
    } else {
      ++it;
    }
  }
  for (auto it = textures_.begin(); it != textures_.end();) {
    if (frame_ - it->second.last_frame > kEvictFrames || (cache_bytes_ > budget_ && it->second.last_frame != frame_)) {
      cache_bytes_ -= it->second.bytes;
      glDeleteTextures(1, &it->second.texture);
      it = textures_.erase(it);
    } else {
      ++it;
    }
  }
}

Image GpuBackend::color_image() const {
  fetch(kColor);
  return resolve_color(samples_, ssaa_);
}
Image GpuBackend::depth_image() const {
  fetch(kDepth);
  return resolve_depth(samples_, ssaa_);
}
void GpuBackend::read_color(uint8_t* rgba, size_t row_bytes, int channels) const {
  if (ssaa_ == 1 && channels == 4 && row_bytes % 4 == 0 && direct_read(rgba, row_bytes)) return;
  if (ssaa_ > 1 && channels == 4 && row_bytes % 4 == 0 && resolve_on_gpu(rgba, row_bytes)) return;
  fetch(kColor);
  velocity::read_color(samples_, ssaa_, &pool(), rgba, row_bytes, channels);
}
void GpuBackend::read_view_depth(float* out) const {
  fetch(kDepth);
  velocity::read_view_depth(samples_, ssaa_, &pool(), projection_, out);
}
void GpuBackend::read_window_depth(float* out) const {
  fetch(kDepth);
  velocity::read_window_depth(samples_, ssaa_, &pool(), out);
}

// The super-sampling resolve (build_resolve_program: the CPU's integer box filter) into
// resolve_'s w x h output; returns that output's framebuffer. The context is current
// and the sample buffer fits a texture.
GLuint GpuBackend::resolve_pass() const {
  const int sw = width_ * ssaa_, sh = height_ * ssaa_;
  Resolve& r = resolve_;
  if (!r.program) {
    r.program = build_resolve_program();
    glGenVertexArrays(1, &r.vao), glGenTextures(1, &r.samples), glGenRenderbuffers(1, &r.output);
    glGenFramebuffers(2, r.framebuffers);
  }
  if (r.width != width_ || r.height != height_ || r.ssaa != ssaa_) {
    glBindTexture(GL_TEXTURE_2D, r.samples);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, sw, sh, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, r.framebuffers[0]);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, r.samples, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, r.output);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
    glBindFramebuffer(GL_FRAMEBUFFER, r.framebuffers[1]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, r.output);
    check_gl("the GPU resolve's buffers");
    r.width = width_, r.height = height_, r.ssaa = ssaa_;
  }
  // The samples into the texture (the drawn framebuffer's colour is a renderbuffer),
  // then one triangle over the output.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.framebuffers[0]);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glBlitFramebuffer(0, 0, sw, sh, 0, 0, sw, sh, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, r.framebuffers[1]);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glViewport(0, 0, width_, height_);
  glDisable(GL_DEPTH_TEST), glDisable(GL_SCISSOR_TEST), glDisable(GL_BLEND), glDisable(GL_CULL_FACE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glUseProgram(r.program);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, r.samples);
  glBindSampler(0, 0);
  glUniform1i(glGetUniformLocation(r.program, "u_samples"), 0);
  glUniform1i(glGetUniformLocation(r.program, "u_k"), ssaa_);
  glBindVertexArray(r.vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  return r.framebuffers[1];
}

// With super-sampling, RGBA rows are resolved on the GPU (build_resolve_program: the
// CPU's integer box filter) and only the w x h output crosses the bus, not k x k times
// as many samples. False when the colour was already fetched, as direct_read.
bool GpuBackend::resolve_on_gpu(uint8_t* rgba, size_t row_bytes) const {
  std::lock_guard<std::mutex> lock(fetch_mutex_);
  const int sw = width_ * ssaa_, sh = height_ * ssaa_;
  // (A sample buffer larger than a texture may be: the samples are read, as fetch does.)
  if (!(pending_ & kColor) || sw > max_texture_ || sh > max_texture_) return false;
  const auto t0 = std::chrono::steady_clock::now();
  Current current(*context_);
  GpuTimer gpu_time(read_query_, gpu_reads_ms_);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_pass());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, GLint(row_bytes / 4));
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);  // (begin_frame sets the rest of the draws' state)
  check_gl("resolving the GPU frame");
  reads_ms_ += ms_since(t0);
  return true;
}

// Without super-sampling, RGBA rows are the GPU framebuffer's own pixels: read straight
// into the caller's rows (no copy through the tiled samples). False when the colour was
// already fetched (the samples then hold it, and the CPU's read is a copy).
bool GpuBackend::direct_read(uint8_t* rgba, size_t row_bytes) const {
  std::lock_guard<std::mutex> lock(fetch_mutex_);
  if (!(pending_ & kColor)) return false;
  const auto t0 = std::chrono::steady_clock::now();
  Current current(*context_);
  GpuTimer gpu_time(read_query_, gpu_reads_ms_);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, GLint(row_bytes / 4));
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  check_gl("reading the GPU frame back");
  reads_ms_ += ms_since(t0);
  return true;
}

// The windowed path (docs/gpu.md, "In a window"): the frame's colour goes from the
// framebuffer object to the window's back buffer on the GPU (a blit, resolved first
// with super-sampling), never through the CPU; the 2D layer is one texture upload.
void GpuBackend::present_window(int window_width, int window_height, const uint8_t* overlay) {
  if (!context_->windowed()) Backend::present_window(window_width, window_height, overlay);
  Current current(*context_);
  // Where the frame goes: scaled to fit, aspect kept, centred (SDL_RenderSetLogicalSize's rule).
  int vx = 0, vy = 0, vw = window_width, vh = window_height;
  if (int64_t(width_) * window_height > int64_t(height_) * window_width) {  // wider than the window: bars above and below
    vh = std::max(1, int(int64_t(height_) * window_width / width_));
    vy = (window_height - vh) / 2;
  } else {
    vw = std::max(1, int(int64_t(width_) * window_height / height_));
    vx = (window_width - vw) / 2;
  }
  const int gl_y = window_height - vy - vh;  // GL counts rows from the bottom
  const int sw = width_ * ssaa_, sh = height_ * ssaa_;
  GLuint source = fbo_;
  int source_w = sw, source_h = sh;
  if (ssaa_ > 1 && sw <= max_texture_ && sh <= max_texture_) source = resolve_pass(), source_w = width_, source_h = height_;
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glDrawBuffer(GL_BACK);
  glDisable(GL_SCISSOR_TEST), glDisable(GL_DEPTH_TEST), glDisable(GL_STENCIL_TEST), glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE), glDisable(GL_FRAMEBUFFER_SRGB);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glViewport(0, 0, window_width, window_height);
  // Black bars where the frame does not reach (a full-window clear costs as much as the
  // blit on a software driver).
  glClearColor(0, 0, 0, 1);
  glEnable(GL_SCISSOR_TEST);
  const int bars[4][4] = {{0, 0, vx, window_height},
                          {vx + vw, 0, window_width - vx - vw, window_height},
                          {vx, 0, vw, gl_y},
                          {vx, gl_y + vh, vw, window_height - gl_y - vh}};
  for (const auto& b : bars)
    if (b[2] > 0 && b[3] > 0) glScissor(b[0], b[1], b[2], b[3]), glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  // The framebuffer object holds the image top row first (drawn upside down for
  // glReadPixels): the blit turns it over. (A sample buffer larger than a texture is
  // scaled down linearly instead of resolved.)
  glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBlitFramebuffer(0, 0, source_w, source_h, vx, gl_y + vh, vx + vw, gl_y, GL_COLOR_BUFFER_BIT,
                    source == fbo_ && ssaa_ > 1 ? GL_LINEAR : GL_NEAREST);
  // The 2D layer is mostly transparent (a status bar, a line of text): only the box
  // of its visible texels is uploaded and blended.
  int x0 = width_, y0 = height_, x1 = 0, y1 = 0;
  if (overlay) {
    for (int y = 0; y < height_; ++y) {
      const uint8_t* row = overlay + size_t(y) * size_t(width_) * 4;
      int first = 0;
      while (first < width_ && row[first * 4 + 3] == 0) ++first;
      if (first == width_) continue;
      int last = width_ - 1;
      while (row[last * 4 + 3] == 0) --last;
      x0 = std::min(x0, first), x1 = std::max(x1, last + 1), y0 = std::min(y0, y), y1 = y + 1;
    }
  }
  if (x0 < x1) {
    Overlay& o = overlay_;
    if (!o.program) {
      o.program = build_overlay_program();
      glGenVertexArrays(1, &o.vao), glGenTextures(1, &o.texture);
    }
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, o.texture);
    glBindSampler(0, 0);
    if (o.width != width_ || o.height != height_) {
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
      o.width = width_, o.height = height_;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, width_);
    glTexSubImage2D(GL_TEXTURE_2D, 0, x0, y0, x1 - x0, y1 - y0, GL_RGBA, GL_UNSIGNED_BYTE,
                    overlay + (size_t(y0) * size_t(width_) + size_t(x0)) * 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    // Premultiplied "over": the layer's colour plus what is under it times 1 - its alpha.
    // The scissor box covers the window pixels of the texel box (and a pixel more: the
    // shader drops texels outside it, which hold older frames' layers).
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glViewport(vx, gl_y, vw, vh);
    const int sx0 = vx + int(int64_t(x0) * vw / width_), sx1 = vx + int((int64_t(x1) * vw + width_ - 1) / width_);
    const int sy0 = gl_y + vh - int((int64_t(y1) * vh + height_ - 1) / height_), sy1 = gl_y + vh - int(int64_t(y0) * vh / height_);
    glEnable(GL_SCISSOR_TEST);
    glScissor(sx0 - 1, sy0 - 1, sx1 - sx0 + 2, sy1 - sy0 + 2);
    glUseProgram(o.program);
    glUniform1i(glGetUniformLocation(o.program, "u_layer"), 0);
    glUniform4f(glGetUniformLocation(o.program, "u_viewport"), float(vx), float(gl_y), float(vw), float(vh));
    glUniform4i(glGetUniformLocation(o.program, "u_box"), x0, y0, x1, y1);
    glBindVertexArray(o.vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_BLEND), glDisable(GL_SCISSOR_TEST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);  // (begin_frame sets the rest of the draws' state)
  check_gl("presenting the frame in the window");
  context_->check_lost("presenting the frame in the window");
}

void GpuBackend::read_stencil(uint8_t* out) const {
  fetch(kStencil);
  velocity::read_stencil(samples_, ssaa_, out);
}
std::vector<uint32_t> GpuBackend::object_ids() const {
  fetch(kIds);
  return resolve_object_ids(samples_, ssaa_);
}
size_t GpuBackend::framebuffer_bytes() const {
  return samples_.color.size() * 4 + samples_.depth.size() * 4 + samples_.ids.size() * 4;
}

}  // namespace velocity::gpu
