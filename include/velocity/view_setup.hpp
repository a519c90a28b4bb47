// How a model viewer shows a model file, shared by `velocity render`, `velocity view`
// and anything else that opens a file "to look at it": load it, draw its back faces
// (lit from both sides) unless told not to, light it when the file brings no light,
// frame it with the camera, and say why when a frame shows nothing.
//
// Files are untrusted (see load.hpp): scene_from_model throws velocity::Error with a
// message a person can act on. Everything else takes trusted, in-memory data.
#pragma once

#include <string>
#include <vector>

#include "velocity/load.hpp"
#include "velocity/renderer.hpp"
#include "velocity/scene.hpp"

namespace velocity {

// Makes every material of the model two-sided (meshes without materials get a default
// two-sided one). Open meshes (a floor, a bumper) are then visible from both sides, as
// in f3d, MeshLab and most model viewers; closed meshes look the same as before.
void make_two_sided(Model& model);

// Adds the default light when the scene has no light other than ambient (3D Studio
// files often have none, or only an ambient line): a white key light from (0.3, 0.5, 1)
// in world space, over the shoulder of a camera framed by scene_from_model, and an
// ambient 0.2 when the scene has no light at all. A scene with a light of its own is
// left as it is.
void add_default_lights(Scene& scene);

// Loads `path` into a new scene: every material two-sided unless `cull_back_faces`,
// the default light (add_default_lights), and the camera framing the model for an
// image of `aspect` (width / height) from the front right and a little above, a
// three-quarter view that shows a model's shape (in the rest pose). With `animations`,
// the file's animations go there, each NodeAnimation::node an ObjectId of the scene;
// with `skins`, its skins (the scene is then posed by them once, at rest).
// Throws velocity::Error.
Scene scene_from_model(const std::string& path, const LoadOptions& options, bool cull_back_faces, float aspect,
                       std::vector<Animation>* animations = nullptr, std::vector<Skin>* skins = nullptr);

// Why a frame drew nothing, from its statistics, as the end of a sentence that begins
// "nothing was drawn: " ("" when something was drawn). `cull_back_faces`: whether the
// frame culled back faces of one-sided materials (the reason then names them).
std::string explain_empty_frame(const FrameStats& stats, bool cull_back_faces);

}  // namespace velocity
