// Vertex normals for a mesh that brings none (one built by hand): loaders compute
// theirs once (compute_normals, smoothing groups), the renderer averages these per draw.
// And normals as colours, for the normals output (RenderOptions::normals).
#pragma once

#include <cstdint>
#include <vector>

#include "velocity/mesh.hpp"

namespace velocity::geometry {

// Into `out` (one per vertex, its storage kept): the sum of the face normals around
// each vertex, area-weighted and not normalised (the vertex stage normalises them in
// eye space).
void average_normals(const Mesh& mesh, std::vector<Vec3>& out);

// `mesh` with its unit eye-space normals (`model_view`: object to eye) as its colours,
// n -> 0.5 + 0.5 n, into `out`: per face when `flat` or a material is flat (or the mesh
// has no normals), else per vertex. Its textures are dropped; the rest is kept, so that
// an unlit draw of `out` covers the pixels a draw of `mesh` does.
void normals_as_colors(const Mesh& mesh, const Mat4& model_view, bool flat, Mesh& out);
// The unit normal an RGBA8 pixel of such a draw holds.
Vec3 normal_from_color(const uint8_t rgba[4]);

}  // namespace velocity::geometry
