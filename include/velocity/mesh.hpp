// Meshes: one shared vertex list and indexed triangles, plus the generated models.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "velocity/material.hpp"
#include "velocity/math.hpp"

namespace velocity {

struct Triangle {
  uint32_t v[3] = {0, 0, 0};  // counter-clockwise seen from the front
};

struct Bounds {
  Vec3 min, max;
  Vec3 center() const { return (min + max) * 0.5f; }
};

struct Sphere {
  Vec3 center;
  float radius = 0;
};

// A triangle mesh in object coordinates. The vertex attribute arrays are either empty or
// hold exactly one entry per position; the face arrays are either empty or hold exactly
// one entry per triangle. `validate()` checks this and every index.
//
// The object coordinates are never changed by drawing or by an object's transform: the
// pipeline transforms copies (seed 000's "original object co-ordinates").
struct Mesh {
  std::string name;

  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // unit length; empty: computed by compute_normals()
  // Texture coordinates in the engine's convention, whatever the file's: v = 0 is the
  // image's top row (Texture::Level). Each loader converts its format's own (docs/appearance.md).
  std::vector<Vec2> uvs;
  std::vector<Vec2> uvs1;    // a second uv set (glTF TEXCOORD_1), addressed by UvTransform::uv_set
  std::vector<Vec4> tangents;  // unit xyz and handedness w = +-1 (glTF TANGENT); empty: generated when needed
  std::vector<Vec3> colors;  // per-vertex colour in [0, 1] (seed 002's gradient), in the material's ColorSpace
  std::vector<float> alphas;  // per-vertex alpha in [0, 1]; empty: opaque

  std::vector<Triangle> triangles;
  std::vector<Vec3> face_colors;        // per-face colour, overrides the material colour
  std::vector<uint32_t> face_materials;  // index into `materials`
  // Per-face smoothing-group bit mask (3D Studio, OBJ `s`): faces sharing a vertex are
  // averaged only when their masks share a bit. Empty: every face is smooth with all.
  std::vector<uint32_t> smoothing_groups;

  std::vector<Material> materials;

  // The data's revision, for caches of the mesh (the GPU backend's, docs/gpu.md "What
  // is uploaded when"): 0, unmarked, the cache hashes every array each frame to see a
  // change; else a number no other data had, which touch() renews after each change, and
  // the cache trusts it without hashing. Loaders, the Python module, pGL and animation
  // mark what they make and touch what they change; so do the functions below that
  // change a marked mesh. Code that edits a marked mesh's arrays itself calls touch()
  // (or sets 0 to go back to hashing).
  uint64_t revision = 0;
  void touch();

  size_t vertex_count() const { return positions.size(); }
  size_t triangle_count() const { return triangles.size(); }

  // Throws velocity::Error (naming the mesh) when an array has the wrong length, an
  // index is out of range or a face material does not exist.
  void validate() const;
  Bounds bounds() const;
  // A bounding sphere centred on the bounding-box centre.
  Sphere bounding_sphere() const;
};

// Face normal, normalise((b - a) x (c - a)); zero for a degenerate triangle.
Vec3 face_normal(const Mesh& mesh, const Triangle& t);

// Sets one normal per vertex: the area-weighted average of the normals of the faces
// sharing the vertex's *position* (so seams where a file duplicated a vertex for its uv
// stay smooth). With smoothing groups, faces whose masks share no bit are not averaged
// together and vertices are split where needed, so hard edges stay hard.
void compute_normals(Mesh& mesh);

// Moves the mesh to its bounding-box centre and scales it so that its bounding sphere
// about that centre has radius 1 (the benchmark scene convention).
void normalize_to_unit_sphere(Mesh& mesh);

// Generated models, all centred on the origin, with normals and uvs, CCW outwards.
Mesh make_cube(float size = 1.0f);
// UV sphere of radius 1: `segments` around (u along longitude), `segments / 2` rings,
// v = 0 (the image's top row) at the north pole (+Y), as ../shared/tools/glref's
// sphere:SEGS shows it (its v = 1 there, in OBJ's convention); 2 * segments * rings triangles, poles included as
// degenerate quads, the same vertex layout as the benchmark convention. segments >= 3.
Mesh make_sphere(int segments);
// Torus about the Y axis: ring radius `major`, tube radius `minor`.
Mesh make_torus(float major = 0.7f, float minor = 0.3f, int segments = 48, int sides = 24);
// A flat grid in the XZ plane facing +Y, `size` across, cells x cells quads.
Mesh make_plane_grid(float size = 2.0f, int cells = 8);

}  // namespace velocity
