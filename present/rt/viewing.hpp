// What a viewer does with a model file before showing it, shared by `velocity render`
// and `velocity view`: load it, light it when the file has no light, draw its back
// faces (lit from both sides) unless told not to, and say why when a frame shows
// nothing.
#pragma once

#include <string>

#include "velocity/load.hpp"
#include "velocity/renderer.hpp"
#include "velocity/scene.hpp"

namespace velocity::rt {

// Makes every material of the model two-sided (meshes without materials get a default
// two-sided one). Open meshes (a floor, a bumper) are then visible from both sides, as
// in f3d, MeshLab and most model viewers; closed meshes look the same as before.
void make_two_sided(Model& model);

// Adds a key light from over the viewer's shoulder (and a little ambient) when the
// scene has no light other than ambient: 3D Studio files often have none.
void add_default_lights(Scene& scene);

// Loads `path` into a new scene: two-sided unless `cull_back_faces`, default lights,
// camera framing the model from the front right and above. Throws velocity::Error.
Scene scene_from_model(const std::string& path, const LoadOptions& options, bool cull_back_faces, float aspect);

// Why a frame drew nothing, from its statistics ("" when something was drawn).
std::string explain_empty_frame(const FrameStats& stats, bool cull_back_faces);

}  // namespace velocity::rt
