// Vertex normals for a mesh that brings none (one built by hand): loaders compute
// theirs once (compute_normals, smoothing groups), the renderer averages these per draw.
#pragma once

#include <vector>

#include "velocity/mesh.hpp"

namespace velocity::geometry {

// Into `out` (one per vertex, its storage kept): the sum of the face normals around
// each vertex, area-weighted and not normalised (the vertex stage normalises them in
// eye space).
void average_normals(const Mesh& mesh, std::vector<Vec3>& out);

}  // namespace velocity::geometry
