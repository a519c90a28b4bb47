// The raster position (GL 1.5 section 2.13): glRasterPos transforms a point as a vertex
// is, tests it against the view volume, and keeps its window coordinates, colour,
// texture coordinates and eye distance for glBitmap, glDrawPixels and glCopyPixels;
// glWindowPos (GL 1.4) sets it in window coordinates.
#include <cmath>

#include "context.hpp"

namespace velocity::gl {

void Context::raster_pos(Vec4 v) {
  if (in_begin_error()) return;
  update_derived();
  const Vec4 eye = transform_.modelview.back() * v;
  const Vec4 clip = transform_.projection.back() * eye;
  RasterPosition& r = pixels.raster;
  // Outside the view volume or a user clip plane (NaN included) the position is
  // invalid; the rest is kept.
  const bool inside = clip.x >= -clip.w && clip.x <= clip.w && clip.y >= -clip.w && clip.y <= clip.w &&
                      clip.z >= -clip.w && clip.z <= clip.w;
  if (!inside || outside_clip_planes(eye)) {
    r.valid = false;
    return;
  }
  const float d = clip.w == 0 ? 1.0f : 1.0f / clip.w;
  const Box& vp = transform_.viewport;
  const float n = transform_.depth_near, f = transform_.depth_far;
  r.window = {float(vp.x) + (clip.x * d + 1) * 0.5f * float(vp.width),
              float(vp.y) + (clip.y * d + 1) * 0.5f * float(vp.height), n + (clip.z * d + 1) * 0.5f * (f - n), clip.w};
  r.valid = true;
  r.color = lighting_.enabled ? lit_front(eye) : Vec4{unit(color_.x), unit(color_.y), unit(color_.z), unit(color_.w)};
  make_live(0);  // unit 0's coordinates, and unit 1's (multitexture.cpp)
  r.texcoord = transform_.texture.back() * (tex_gen_.any() ? generate_texcoord(v, eye) : texcoord_);
  parked_unit_.matrix_identity = parked_unit_.matrix.back() == Mat4{};
  raster_texcoord1_ = unit1_texcoord(v, eye);
  make_live(active_unit_);
  r.distance = std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
}

// GL 1.4 section 2.12: x and y as given, z through the depth range, always valid; the
// current colour unlit and the texture coordinates untransformed; distance 0.
void Context::window_pos(Vec3 v) {
  if (in_begin_error()) return;
  RasterPosition& r = pixels.raster;
  const float n = transform_.depth_near, f = transform_.depth_far;
  r.window = {v.x, v.y, n + unit(v.z) * (f - n), 1};
  r.valid = true;
  r.color = {unit(color_.x), unit(color_.y), unit(color_.z), unit(color_.w)};
  r.texcoord = texcoord_;
  r.distance = 0;
}

}  // namespace velocity::gl
