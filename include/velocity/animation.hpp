// Node animations: glTF 2.0's translation / rotation / scale channels, and the pose of
// a node at a time. The loader reads them (Model::animations, glTF only); a program
// plays them by setting each animated object's `base` matrix every frame (apply).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "velocity/math.hpp"
#include "velocity/scene.hpp"

namespace velocity {

// A rotation as a unit quaternion (x, y, z: the axis times sin(angle / 2); w: cos).
struct Quat {
  float x = 0, y = 0, z = 0, w = 1;
};

// How a channel goes from one key to the next (glTF's sampler "interpolation"):
// Linear lerps (slerps rotations), Step holds each key until the next one.
// CUBICSPLINE samplers are read as Linear through their keys' values.
enum class Interpolation { Linear, Step };

template <typename T>
struct Keys {
  std::vector<float> times;  // seconds, increasing
  std::vector<T> values;     // one per time
  Interpolation interpolation = Interpolation::Linear;
  bool empty() const { return times.empty(); }
};

// One node's channels; a part without keys keeps the node's rest value.
struct NodeAnimation {
  size_t node = 0;  // Model::nodes index (a Scene's ObjectId once in a scene)
  Vec3 rest_translation;
  Quat rest_rotation;
  Vec3 rest_scale{1, 1, 1};
  Keys<Vec3> translation;
  Keys<Quat> rotation;
  Keys<Vec3> scale;
};

// A mesh's morph targets (glTF): each target's offset of every vertex's position and
// normal, in the order of `base`'s vertices (a target without normals: none).
struct MorphTargets {
  std::shared_ptr<const Mesh> base;  // the mesh with every weight zero
  std::vector<std::vector<Vec3>> positions, normals;  // [target][vertex]
  std::vector<float> rest_weights;                   // the mesh's "weights", else zeros
};

// A node's morph target weights over time (one value per target a key) and its mesh's
// targets.
struct MorphAnimation {
  size_t node = 0;  // as NodeAnimation::node
  Keys<std::vector<float>> weights;
  std::shared_ptr<const MorphTargets> targets;
};

struct Animation {
  std::string name;
  float duration = 0;  // the last key's time, seconds
  std::vector<NodeAnimation> nodes;
  std::vector<MorphAnimation> morphs;
};

// A skinned mesh (a glTF skin): each vertex of `base` (the bind pose) moved by up to
// four joints, by weight. Nodes are as NodeAnimation::node (ObjectIds in a scene).
struct Skin {
  size_t node = 0;  // the object whose mesh is skinned
  std::shared_ptr<const Mesh> base;
  std::vector<size_t> joints;
  std::vector<Mat4> inverse_bind;  // one per joint: from the mesh's space to the joint's at bind
  std::vector<std::array<uint16_t, 4>> vertex_joints;  // indices into `joints`, one set a vertex
  std::vector<std::array<float, 4>> vertex_weights;
};

// The spherical interpolation from `a` to `b` by `u` in [0, 1], the short way round.
Quat slerp(Quat a, Quat b, float u);
// The rotation matrix of `q` (normalised first; a zero quaternion is no rotation).
Mat4 rotation_matrix(Quat q);

// A channel's value at time `t` (before the first key: the first; after the last: the
// last); `rest` when it has no keys.
Vec3 sample(const Keys<Vec3>& keys, float t, Vec3 rest);
Quat sample(const Keys<Quat>& keys, float t, Quat rest);
std::vector<float> sample(const Keys<std::vector<float>>& keys, float t, const std::vector<float>& rest);

// `targets.base` with each target added in by its weight (missing weights count as zero);
// normals renormalised. Throws nothing: targets of another length than the mesh are skipped.
Mesh morph(const MorphTargets& targets, const std::vector<float>& weights);

// The node's local matrix at `t`: translation * rotation * scale.
Mat4 pose(const NodeAnimation& node, float t);

// Sets the `base` matrix of every animated object of `scene` to its pose at `t`, and
// the mesh of every morphed one to its mesh at the weights at `t` (NodeAnimation::node
// and MorphAnimation::node are ObjectIds there; ids not in the scene are skipped).
void apply(const Animation& animation, float t, Scene& scene);
// Sets each skin's object's mesh to its base with every vertex moved by its joints as
// they stand in `scene` now (after apply): the weighted sum of inverse(the object's world
// matrix) * the joint's world matrix * its inverse bind matrix, as glTF specifies.
// Normals turn with it (renormalised). A vertex whose weights add to zero stays put; a
// skin whose arrays do not match its base or whose ids are not in the scene is skipped.
void skin(const std::vector<Skin>& skins, Scene& scene);

// A still of an animated file: `scene` posed at `time` seconds of `animations[index]`
// (after its end: its last pose), then its skins moved by the joints. Throws
// velocity::Error saying how many animations there are when `index` is past them, and
// when `time` is negative or not finite.
void pose_at(const std::vector<Animation>& animations, size_t index, float time, const std::vector<Skin>& skins,
             Scene& scene);

// Puts every object `animation` moves back at its rest pose and rest weights (before another animation
// plays: nodes only the first one moves would otherwise keep its last pose).
void rest(const Animation& animation, Scene& scene);

}  // namespace velocity
