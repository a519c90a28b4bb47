// A frame's draws as the vertex and triangle stages run them: what Renderer::draw
// recorded, with everything decided once per draw (matrices, per-material kernels,
// which vertex outputs are needed), and the frame-wide per-vertex arrays the vertex
// stage fills.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/viewport.hpp"
#include "raster/contract.hpp"
#include "shading/lighting.hpp"
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
  // Pbr: the kernel's inputs (raster::pbr_kernel), the uv set its textures read, blended.
  bool pbr_tangents = false, pbr_colors = false, blend = false;
  int uv_set = 0;
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
  const std::vector<Vec4>* tangents = nullptr; // the mesh's, or generated, when a material maps normals
  uint32_t slot_begin = 0, slot_count = 0;     // into the frame's slots
  size_t vertex_base = 0;                      // into the frame's vertex arrays
  bool light = false, normal = false, eye = false;  // which vertex outputs are needed
  // Every face has one base colour (uniform_color): the vertex stage writes the lit,
  // clamped colour itself (vertex_color); otherwise light terms, and the specular ones
  // only when the material has a highlight.
  bool vertex_color = false, vertex_specular_terms = false;
  Vec3 uniform_color;
  bool cull_all = true;   // every material culls back faces
  bool needs_tangents = false;  // a Pbr material has a normal map
  bool blend = false;           // a material blends (AlphaMode::Blend): drawn after the opaque draws
  Vec3 centre;                  // the bounding sphere's centre, eye space (blended draws' order)
  bool fill_only = true;  // no material draws wireframe or points
  shading::Specular vertex_specular;                   // what the vertex stage lit with
};

// A Renderer::draw(batch, state) call.
struct BatchDrawPlan {
  PrimitiveBatch batch;
  uint32_t draw_state = 0;
  uint8_t kernel = 0;
  bool textured = false, fog = false;
  int units = 0;           // texture units read (textured: 1 or 2)
  int volumes = 0;         // bit u: unit u's texture is 3-D (s, t, r, q interpolated)
  bool color_sum = false;  // a secondary colour added after texturing
  int num_varyings = 0;
  uint32_t primitive_count = 0;
  ViewportMap viewport{};
  SetupParams setup;
  size_t vertex_base = 0;
  // Its vertices' vertex-stage outputs (in DrawList::vertices at vertex_base, or the
  // renderer's own arrays for a batch it ran before end_frame).
  const ProjectedVertex* projected = nullptr;
  const uint32_t* codes = nullptr;
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

// A frame's draws: everything the triangle stage reads, immutable while it runs.
struct DrawList {
  int width = 0, height = 0;  // the sample buffer
  GuardBand guard{};
  ViewportMap viewport{};     // the whole framebuffer, for meshes
  shading::EyeLights lights;
  RenderOptions options;
  // The frame's colour pipeline (RenderOptions::color resolved, finish_color_plan):
  // colours decoded to linear light and the output encoded to sRGB.
  bool linear = false;
  SetupParams mesh_setup;
  std::vector<MeshDrawPlan> meshes;
  std::vector<BatchDrawPlan> batches;
  std::vector<ClearPlan> clears;
  std::vector<SlotPlan> slots;
  VertexArrays vertices;
};

// Fills d's slots (one per material, with its kernel and DrawState) and decides which
// vertex outputs the draw needs. `default_material` is slot 0 when there is no override.
void plan_mesh_draw(DrawList& plan, std::vector<raster::DrawState>& states, MeshDrawPlan& d, const Material* override,
                    const Material& default_material);

// At end_frame, once every draw is known: resolves ColorPipeline::Auto (Linear when a
// slot is Pbr) into plan.linear and puts each draw's colours and textures into that
// pipeline's space (uniform colours, line colours, base colour factors, sRGB decoding).
void finish_color_plan(DrawList& plan, std::vector<raster::DrawState>& states);

// A colour given in `space`, in the pipeline's: linear light, or display values.
Vec3 pipeline_color(Vec3 c, ColorSpace space, bool linear);

// Plans a Renderer::draw(batch, state) of `primitives` primitives: its kernel, its
// viewport (within the guard band's reach of the framebuffer), the pixels set-up may
// touch (viewport and scissor) and its DrawState, appended to `states`.
BatchDrawPlan plan_batch_draw(const DrawList& plan, std::vector<raster::DrawState>& states, const PrimitiveBatch& batch,
                              const PixelState& state, uint32_t primitives);

}  // namespace velocity::geometry
