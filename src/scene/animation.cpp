#include "velocity/animation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "velocity/error.hpp"

namespace velocity {

namespace {

Vec3 lerp(Vec3 a, Vec3 b, float u) { return a + (b - a) * u; }
Quat lerp(Quat a, Quat b, float u) { return slerp(a, b, u); }
std::vector<float> lerp(const std::vector<float>& a, const std::vector<float>& b, float u) {
  std::vector<float> out(std::min(a.size(), b.size()));
  for (size_t i = 0; i < out.size(); ++i) out[i] = a[i] + (b[i] - a[i]) * u;
  return out;
}

// The key interval holding `t`, and how far into it; shared by both value types.
template <typename T>
T sample_keys(const Keys<T>& k, float t, T rest) {
  const size_t n = std::min(k.times.size(), k.values.size());
  if (n == 0) return rest;
  if (!(t > k.times[0])) return k.values[0];  // NaN too
  if (t >= k.times[n - 1]) return k.values[n - 1];
  const size_t i = size_t(std::upper_bound(k.times.begin(), k.times.begin() + ptrdiff_t(n), t) - k.times.begin()) - 1;
  if (k.interpolation == Interpolation::Step) return k.values[i];
  const float span = k.times[i + 1] - k.times[i];
  const float u = span > 0 ? std::clamp((t - k.times[i]) / span, 0.0f, 1.0f) : 1.0f;
  return lerp(k.values[i], k.values[i + 1], u);
}

}  // namespace

Quat slerp(Quat a, Quat b, float u) {
  float d = a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
  if (d < 0) b = {-b.x, -b.y, -b.z, -b.w}, d = -d;  // q and -q are the same rotation
  float wa = 1 - u, wb = u;
  if (d < 0.9995f) {  // else nearly parallel: the straight line is as good, and stable
    const float angle = std::acos(std::min(d, 1.0f)), s = std::sin(angle);
    wa = std::sin((1 - u) * angle) / s, wb = std::sin(u * angle) / s;
  }
  Quat q{wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z, wa * a.w + wb * b.w};
  const float len = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  return len > 0 && std::isfinite(len) ? Quat{q.x / len, q.y / len, q.z / len, q.w / len} : Quat{};
}

Mat4 rotation_matrix(Quat q) {
  const float len = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (!(len > 0) || !std::isfinite(len)) return Mat4::identity();
  const float x = q.x / len, y = q.y / len, z = q.z / len, w = q.w / len;
  Mat4 r;
  r.m[0][0] = 1 - 2 * (y * y + z * z), r.m[0][1] = 2 * (x * y - z * w), r.m[0][2] = 2 * (x * z + y * w);
  r.m[1][0] = 2 * (x * y + z * w), r.m[1][1] = 1 - 2 * (x * x + z * z), r.m[1][2] = 2 * (y * z - x * w);
  r.m[2][0] = 2 * (x * z - y * w), r.m[2][1] = 2 * (y * z + x * w), r.m[2][2] = 1 - 2 * (x * x + y * y);
  return r;
}

Vec3 sample(const Keys<Vec3>& keys, float t, Vec3 rest) { return sample_keys(keys, t, rest); }
Quat sample(const Keys<Quat>& keys, float t, Quat rest) { return sample_keys(keys, t, rest); }

std::vector<float> sample(const Keys<std::vector<float>>& keys, float t, const std::vector<float>& rest) {
  return sample_keys(keys, t, rest);
}

Mesh morph(const MorphTargets& targets, const std::vector<float>& weights) {
  Mesh out = *targets.base;
  const size_t n = out.positions.size();
  bool normals = false;
  for (size_t k = 0; k < weights.size(); ++k) {
    const float w = weights[k];
    if (w == 0 || !std::isfinite(w)) continue;
    if (k < targets.positions.size() && targets.positions[k].size() == n)
      for (size_t v = 0; v < n; ++v) out.positions[v] += targets.positions[k][v] * w;
    if (k < targets.normals.size() && targets.normals[k].size() == n && out.normals.size() == n) {
      for (size_t v = 0; v < n; ++v) out.normals[v] += targets.normals[k][v] * w;
      normals = true;
    }
  }
  if (normals)
    for (Vec3& v : out.normals)
      if (const float len = length(v); len > 1e-12f && std::isfinite(len)) v = v * (1 / len);
  out.touch();  // new data: the base's revision is not this mesh's (Mesh::revision)
  return out;
}

void skin(const std::vector<Skin>& skins, Scene& scene) {
  if (skins.empty()) return;
  const std::vector<Mat4> world = scene.world_matrices();
  for (const Skin& s : skins) {
    const size_t n = s.base ? s.base->positions.size() : 0;
    bool fits = s.base && s.node < world.size() && s.inverse_bind.size() == s.joints.size() &&
                s.vertex_joints.size() == n && s.vertex_weights.size() == n;
    for (size_t j : s.joints) fits &= j < world.size();
    Mat4 to_mesh;
    if (!fits || !invert(world[s.node], to_mesh)) continue;
    std::vector<Mat4> joint(s.joints.size());
    for (size_t j = 0; j < joint.size(); ++j) joint[j] = to_mesh * world[s.joints[j]] * s.inverse_bind[j];
    Mesh out = *s.base;
    const bool normals = out.normals.size() == n;
    for (size_t v = 0; v < n; ++v) {
      Vec3 p, nn;
      float total = 0;
      for (int k = 0; k < 4; ++k) {
        const float w = s.vertex_weights[v][k];
        if (!(w > 0) || s.vertex_joints[v][k] >= joint.size()) continue;  // NaN too
        const Mat4& m = joint[s.vertex_joints[v][k]];
        p += m.transform_point(s.base->positions[v]) * w;
        if (normals) nn += m.transform_vector(s.base->normals[v]) * w;
        total += w;
      }
      if (!(total > 0) || !std::isfinite(total)) continue;
      out.positions[v] = p * (1 / total);
      if (const float len = length(nn); normals && len > 1e-12f && std::isfinite(len)) out.normals[v] = nn * (1 / len);
    }
    out.touch();  // (as morph)
    scene.object(ObjectId(s.node)).mesh = std::make_shared<const Mesh>(std::move(out));
  }
}

Mat4 pose(const NodeAnimation& node, float t) {
  return translate(sample(node.translation, t, node.rest_translation)) *
         rotation_matrix(sample(node.rotation, t, node.rest_rotation)) * scale(sample(node.scale, t, node.rest_scale));
}

void apply(const Animation& animation, float t, Scene& scene) {
  for (const NodeAnimation& n : animation.nodes)
    if (n.node < scene.objects().size()) scene.object(ObjectId(n.node)).base = pose(n, t);
  for (const MorphAnimation& m : animation.morphs)
    if (m.node < scene.objects().size() && m.targets && m.targets->base)
      scene.object(ObjectId(m.node)).mesh =
          std::make_shared<const Mesh>(morph(*m.targets, sample(m.weights, t, m.targets->rest_weights)));
}

void pose_at(const std::vector<Animation>& animations, size_t index, float time, const std::vector<Skin>& skins,
             Scene& scene) {
  if (!(time >= 0 && std::isfinite(time)))
    throw Error("animation time must be 0 or more seconds, got " + std::to_string(time));
  if (index >= animations.size())
    throw Error("animation " + std::to_string(index) + ": the file has " + std::to_string(animations.size()) +
                " animation" + (animations.size() == 1 ? "" : "s") +
                (animations.empty() ? "" : " (0.." + std::to_string(animations.size() - 1) + ")"));
  apply(animations[index], time, scene);
  skin(skins, scene);  // the joints moved
}

void rest(const Animation& animation, Scene& scene) {
  for (const NodeAnimation& n : animation.nodes)
    if (n.node < scene.objects().size())
      scene.object(ObjectId(n.node)).base =
          translate(n.rest_translation) * rotation_matrix(n.rest_rotation) * scale(n.rest_scale);
  for (const MorphAnimation& m : animation.morphs)
    if (m.node < scene.objects().size() && m.targets && m.targets->base)
      scene.object(ObjectId(m.node)).mesh = std::make_shared<const Mesh>(morph(*m.targets, m.targets->rest_weights));
}

}  // namespace velocity
