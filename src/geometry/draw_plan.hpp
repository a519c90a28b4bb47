// A frame's draws as the geometry stage runs them: what Renderer::draw recorded, with
// everything decided once per draw (matrices, per-material kernels, which vertex
// outputs are needed), and the frame-wide per-vertex arrays the vertex stage fills.
#pragma once

#include <cstdint>
#include <vector>

#include "shading/lighting.hpp"
#include "geometry/vertex_stage.hpp"
#include "raster/bins.hpp"
#include "raster/rasterize.hpp"
#include "raster/setup.hpp"
#include "velocity/mesh.hpp"
#include "velocity/primitives.hpp"
#include "velocity/renderer.hpp"

namespace velocity::geometry {

// How one material of a mesh draw is drawn.
struct SlotPlan {
  const Material* material = nullptr;
  Shading shading = Shading::Gouraud;
  uint8_t kernel = 0;       // raster::KernelId (with the filter)
  int num_varyings = 0;
  bool cull = true;         // back faces culled
  bool lit = true;          // Gouraud's per-vertex lighting (false: unlit colours)
  bool uv_from_env = false; // flat/Gouraud environment mapping: per-vertex normal -> uv
  bool white = false;       // "replace": the texture as it is, unlit
  bool flat = false;        // one colour per face
  bool vertex_light_ok = false;  // the vertex stage's light terms were computed for this material
  bool vertex_color = false;     // ... and its lit colour (MeshDrawPlan::vertex_color)
  shading::Specular specular;
  uint32_t draw_state = 0;  // index into the frame's DrawStates
  uint32_t line_color = 0;  // RGBA8 for wireframe and points
};

// A Renderer::draw(mesh, ...) call.
struct MeshDrawPlan {
  const Mesh* mesh = nullptr;
  const Material* override_material = nullptr;
  uint32_t object_id = 0;
  Mat4 model_view, mvp, normal_matrix;
  const std::vector<Vec3>* normals = nullptr;  // the mesh's, or averaged for this draw
  uint32_t slot_begin = 0, slot_count = 0;     // into the frame's slots
  size_t vertex_base = 0;                      // into the frame's vertex arrays
  bool light = false, normal = false, eye = false;  // which vertex outputs are needed
  // Every face has one base colour (uniform_color): the vertex stage writes the lit,
  // clamped colour itself (vertex_color); otherwise light terms, and the specular ones
  // only when the material has a highlight.
  bool vertex_color = false, vertex_specular_terms = false;
  Vec3 uniform_color;
  bool cull_all = true;   // every material culls back faces
  bool fill_only = true;  // no material draws wireframe or points
  shading::Specular vertex_specular;                   // what the vertex stage lit with
};

// A Renderer::draw(batch, state) call.
struct BatchDrawPlan {
  PrimitiveBatch batch;
  uint32_t draw_state = 0;
  uint8_t kernel = 0;
  bool textured = false, fog = false;
  int num_varyings = 0;
  uint32_t primitive_count = 0;
  ViewportMap viewport{};
  raster::SetupParams setup;
  size_t vertex_base = 0;
};

struct ClearPlan {
  ClearRequest request;
  int x0, y0, x1, y1;  // inclusive pixel box
};

// The per-vertex arrays of a frame, shared by its draws (each at its vertex_base).
struct VertexArrays {
  std::vector<ProjectedVertex> projected;
  std::vector<uint32_t> codes;
  std::vector<Vec3> diffuse, specular, normal, eye;
};

// Everything the triangle stage reads, immutable while it runs.
struct FramePlan {
  int width = 0, height = 0;  // the sample buffer
  GuardBand guard{};
  ViewportMap viewport{};     // the whole framebuffer, for meshes
  shading::EyeLights lights;
  RenderOptions options;
  raster::SetupParams mesh_setup;
  std::vector<MeshDrawPlan> meshes;
  std::vector<BatchDrawPlan> batches;
  std::vector<ClearPlan> clears;
  std::vector<SlotPlan> slots;
  VertexArrays vertices;
};

// The most triangles (or primitives) one job of the triangle stage holds.
inline constexpr uint32_t kTrianglesPerJob = 4096;

// One piece of the triangle stage: a range of one draw's primitives, or a clear.
struct Job {
  enum class Kind : uint8_t { Mesh, Batch, Clear } kind;
  uint32_t draw;         // index into meshes, batches or clears
  uint32_t begin, end;   // primitives
  size_t nonfinite = 0;  // filled in by the worker that ran it
};

// What one worker needs while it runs jobs of the triangle stage.
struct StageContext {
  raster::WorkerBins& bins;
  FrameStats& stats;
  uint32_t job = 0;
  size_t nonfinite = 0;  // triangles of this job dropped for NaN/Inf
  // The worker's scratch for the first pass's survivors (kTrianglesPerJob each).
  uint32_t* direct = nullptr;
  uint32_t* info = nullptr;
  uint32_t* clipped = nullptr;
  std::vector<uint8_t>* marks = nullptr;  // points: which vertices this job drew

  // The record goes to the tiles (raster/bins.hpp decides when).
  void emit(raster::RecordHeader& r, uint32_t ref, float sort_key) { bins.emit(job, r, ref, sort_key); }
};

// Fills d's slots (one per material, with its kernel and DrawState) and decides which
// vertex outputs the draw needs. `default_material` is slot 0 when there is no override.
void plan_mesh_draw(FramePlan& plan, std::vector<raster::DrawState>& states, MeshDrawPlan& d, const Material* override,
                    const Material& default_material);

// The triangle stage for one job: assemble, reject, cull, clip, set up and bin.
void run_mesh_job(const FramePlan& plan, const MeshDrawPlan& draw, uint32_t begin, uint32_t end, StageContext& cx);
void run_batch_job(const FramePlan& plan, const BatchDrawPlan& draw, uint32_t begin, uint32_t end, StageContext& cx);
void run_clear_job(const ClearPlan& clear, int width, int height, StageContext& cx);

}  // namespace velocity::geometry
