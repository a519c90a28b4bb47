// Tangents for normal mapping when a mesh brings none (glTF's TANGENT is optional).
// glTF asks for MikkTSpace's; Debian 12 packages no MikkTSpace library, so these are
// Lengyel's per-vertex tangents: each face's dP/du (area-weighted, as its uv map gives
// it) summed at its corners, made orthogonal to the vertex normal, with the handedness
// of -dP/dv (glTF's bitangent points up the image). They agree with MikkTSpace's on meshes whose uv charts are continuous at
// the vertices (no mirrored halves sharing a vertex); docs/appearance.md says more.
#pragma once

#include <vector>

#include "velocity/mesh.hpp"

namespace velocity::geometry {

// Into `out` (one per vertex, its storage kept): unit tangents and handedness (w = +-1)
// from `uvs` and `normals` (both one per vertex). A vertex whose faces have no uv
// extent gets a tangent perpendicular to its normal.
void generate_tangents(const Mesh& mesh, const std::vector<Vec3>& normals, const std::vector<Vec2>& uvs,
                       std::vector<Vec4>& out);

}  // namespace velocity::geometry
