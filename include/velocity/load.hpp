// Loading models and images from files.
//
// Files are untrusted: every loader validates what it reads and throws velocity::Error
// with the file name, the line (text formats) and what was expected. A failed load
// leaves nothing behind; no count read from a file is trusted for an allocation.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "velocity/animation.hpp"
#include "velocity/image.hpp"
#include "velocity/mesh.hpp"
#include "velocity/scene.hpp"

namespace velocity {

struct LoadOptions {
  // 3D Studio stores Z up; Velocity is Y up (both right-handed). With swap_yz, ASC
  // coordinates (lights and cameras included) are turned -90 degrees about X:
  // (x, y, z) -> (x, z, -y). That is a rotation, not a mirror, so models stand upright,
  // keep their handedness (no mirror image), and their counter-clockwise front faces
  // stay front-facing; 3D Studio's front view (looking along +Y) becomes Velocity's
  // default view (looking along -Z). A plain swap (x, z, y) would also stand them up,
  // but mirrored, with every winding flipped: seed 000's "Errors found" fix, not used.
  // Off: coordinates as written. ASC only (PLG files are Y up already; see load_plg).
  bool swap_yz = true;
  // Most the loader may allocate for one file, in bytes (vertices, faces, images).
  size_t max_memory = size_t(2) << 30;
  // load_model: load the texture files materials name (Material::texture_file), found
  // next to the model; a missing one is a warning, not an error.
  bool load_textures = true;
};

// One named part of a model: a mesh (or none, for a pure transform node), its matrix
// relative to its parent node, and the parent's index in Model::nodes (-1 for a root).
// Parents come before their children.
struct ModelNode {
  std::string name;
  std::shared_ptr<Mesh> mesh;
  Mat4 local;
  int parent = -1;
};

struct NamedCamera {
  std::string name;
  Camera camera;
};

// Everything a file held: meshes in a node hierarchy, its lights and cameras.
struct Model {
  std::string path;
  std::vector<ModelNode> nodes;
  std::vector<Light> lights;
  std::vector<NamedCamera> cameras;
  // glTF node animations (translation, rotation, scale) and morph target weights,
  // moving and morphing `nodes` by index.
  std::vector<Animation> animations;
  // glTF skins, on `nodes` by index: skin(skins, scene) after each apply.
  std::vector<Skin> skins;

  size_t vertex_count() const;
  size_t triangle_count() const;
};

// Loads a model, choosing the reader by the file's extension (case-insensitive):
// .asc (3D Studio ASCII), .plg/.plx (REND386 / Black Art / T3D), .obj; .gltf, .glb,
// .3ds, .ply and .stl through load_with_assimp.
Model load_model(const std::string& path, const LoadOptions& options = {});

// The readers themselves; `name` is used in error messages.
//
// ASC: one node per Tri-mesh (vertices are in world space: Model nodes' `local` is the
// identity), normals from compute_normals() with the file's smoothing groups, one
// Material per distinct per-face "Material:" name ("rNNNgNNNbNNNaN" names set the
// colour; texture file names are kept in Material::name). The ambient colour becomes
// an Ambient light; each "Direct light" (3D Studio's omni light) a Point light without
// attenuation; each camera a NamedCamera (fov from the focal length, looking at its
// target, roll = bank angle, near/far fitted around the model: 3D Studio's Near/Far
// are fog ranges).
Model load_asc(const std::string& path, const LoadOptions& options = {});
Model parse_asc(std::string_view text, const std::string& name, const LoadOptions& options = {});
// PLG (Black Art of 3D Game Programming) and PLX (Tricks of the 3D Game Programming
// Gurus): one node; polygons fanned into triangles; one Material per distinct polygon
// descriptor (named after it, "0x109f"). The books' worlds are left-handed with Y up:
// z is negated, and the winding made counter-clockwise-front per dialect, so faces
// point outwards. See src/io/plg.cpp and src/io/plg.hpp for the descriptor bits.
Model load_plg(const std::string& path, const LoadOptions& options = {});
Model parse_plg(std::string_view text, const std::string& name, const LoadOptions& options = {});
Model load_obj(const std::string& path, const LoadOptions& options = {});

// glTF 2.0 (.gltf, .glb), 3D Studio (.3ds), PLY (.ply) and STL (.stl), ASCII and binary,
// through Assimp (src/io/assimp_adapter.cpp), chosen by the extension; other
// extensions are refused (Assimp reads more formats, but only these are tested here,
// damaged files included).
// One ModelNode per node of the file, the root included, parents first, `local` its
// matrix; a node's meshes (a glTF mesh's primitives) merged into one Mesh with one
// Material per primitive material and per-face material indices. glTF materials are
// Shading::Pbr in ColorSpace::Linear with everything glTF 2.0's metallic-roughness
// model, KHR_materials_unlit, KHR_texture_transform and KHR_materials_emissive_strength
// say, their images decoded (inside the file or beside it; docs/appearance.md); the
// other formats' are the diffuse colour, specular, two-sidedness and flat / Phong /
// unlit shading, with the texture file named. Normals from the file when it has usable
// ones, else compute_normals(); uvs from channels 0 and 1 in the engine's convention
// (v = 0 at the image's top row); glTF tangents; per-vertex colours and alphas (glTF
// COLOR_0, PLY red/green/blue) as the file has them. Vertices keep the file's indexing
// (STL: three per triangle; 3D Studio: three per face). Points (a PLY file without
// faces, glTF POINTS) become a point cloud: one triangle (v, v, v) per point, drawn by
// a Shading::Points material (RenderOptions::point_size); lines are dropped with a
// warning. glTF cameras (perspective and orthographic) become
// NamedCameras placed by their node, KHR_lights_punctual lights Lights (intensity times
// colour, inverse-square falloff with the range); 3D Studio cameras are not converted
// (Assimp 5.2 loses their target), nor are 3D Studio lights. glTF node animations
// (translation, rotation, scale; float keys) and morph target weights (with the POSITION
// and NORMAL targets of the node's mesh) are read by Velocity from the JSON into
// Model::animations, and skins (JOINTS_0 / WEIGHTS_0, inverse bind matrices) into
// Model::skins (meshes come in their bind pose until skin() poses them).
// Throws velocity::Error naming the file for a missing or malformed file (what
// Velocity's own checks before Assimp found, with the line or byte offset: PLY whole,
// ASCII STL whole, 3D Studio chunks, glTF JSON and node trees; else Assimp's message),
// a file without triangles, a non-finite vertex, and when the files read (a glTF's
// buffers included) or the meshes built would exceed options.max_memory; nothing is
// returned then.
Model load_with_assimp(const std::string& path, const LoadOptions& options = {});

// The texture file that the model file at `model_path` names `name`, or "" when there
// is none. Relative names are looked up in the model's folder: first as written, then
// with backslashes as slashes, then percent-decoded (glTF URIs), each exactly and then
// ignoring ASCII case component by component ("IMAGE1.JPG" finds image1.jpg); last,
// the bare file name beside the model (for paths from the writer's machine, such as
// "C:\maps\wood.jpg"). Embedded images ("*0", "data:" URIs) give "". Reads the file
// system only; never throws for a missing file.
std::string resolve_texture_path(const std::string& model_path, const std::string& name);

// Adds every node of `model` to `scene` as objects (names and hierarchy kept) under
// `parent`, and its lights. Returns the ids of the root nodes' objects.
std::vector<ObjectId> add_to_scene(Scene& scene, const Model& model, ObjectId parent = kNoParent);

}  // namespace velocity
