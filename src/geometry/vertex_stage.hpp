// The vertex stage: per vertex, the clip-space position and its region code, the
// perspective divide and viewport transform with the snap to 24.8 fixed point, and for
// the meshes that need them the eye-space normal and position and the lighting terms.
// Written once against the SIMD layer (N vertices at a time), run on every core over
// chunks of vertices.
#pragma once

#include <cstddef>
#include <cstdint>

#include "geometry/viewport.hpp"
#include "shading/lighting.hpp"
#include "velocity/math.hpp"

namespace velocity::geometry {

struct VertexOutputs {
  ProjectedVertex* projected = nullptr;
  uint32_t* codes = nullptr;
  Vec3* diffuse = nullptr;   // with lighting: ambient + diffuse light, before the base colour
  Vec3* specular = nullptr;  // and the specular light, scaled by Ks
  Vec3* normal = nullptr;    // unit eye-space normal, when asked for
  Vec3* eye = nullptr;       // eye-space position, when asked for
};

// A chunk [begin, end) of a mesh's vertices. Outputs are indexed like the positions.
struct MeshVertexJob {
  const Vec3* positions = nullptr;
  const Vec3* normals = nullptr;  // needed for lighting and normal output
  size_t begin = 0, end = 0;
  Mat4 mvp, model_view, normal_matrix;
  ViewportMap viewport{};
  const shading::EyeLights* lights = nullptr;  // set: compute diffuse and specular
  shading::Specular specular;
  // With lighting: when set, the lit colour clamp(base * diffuse + specular) goes to
  // out.diffuse and nothing to out.specular (a draw whose faces share one colour).
  const Vec3* base_color = nullptr;
  VertexOutputs out;
};

// A chunk of pre-transformed (clip-space) vertices.
struct ClipVertexJob {
  const Vec4* positions = nullptr;
  size_t begin = 0, end = 0;
  ViewportMap viewport{};
  VertexOutputs out;  // projected and codes only
};

void transform_mesh_vertices(const MeshVertexJob& job);
void project_clip_vertices(const ClipVertexJob& job);

}  // namespace velocity::geometry
