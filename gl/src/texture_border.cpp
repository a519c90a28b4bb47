// Texture borders (GL 1.x's border = 1 in glTexImage1D/2D/3D and glCopyTexImage1D/2D):
// the sizes given count the border, a ring of texels around the image. A level keeps
// the whole ring with it (Texture::Level::border: width, height and depth are the
// image's inside), and the engine's sampler reads the ring's texels where it would
// read the border colour — GL_CLAMP_TO_BORDER — so the border is what a bordered
// texture blends at its edges; GL_REPEAT, GL_CLAMP_TO_EDGE and GL_MIRRORED_REPEAT never
// reach it. A 1-D image has no border rows: its one row is kept three times, and the
// sampler never reads t outside it. Sub-images and copies address the border at -1;
// glGetTexLevelParameter's sizes and glGetTexImage include it.
#include <algorithm>

#include "context.hpp"

namespace velocity::gl {

Context::BorderAxes Context::border_axes(GLenum target, int border) {
  const bool one_d = target == GL_TEXTURE_1D;
  const bool three_d = target == GL_TEXTURE_3D || target == GL_PROXY_TEXTURE_3D;
  return {border, one_d ? 0 : border, three_d ? border : 0};
}

bool Context::sub_image_inside(GLenum target, const Texture::Level& l, GLint x, GLint y, GLint z, GLsizei w, GLsizei h,
                               GLsizei d) {
  const BorderAxes b = border_axes(target, l.border);
  return x >= -b.x && y >= -b.y && z >= -b.z && int64_t(x) + w <= int64_t(l.width) + b.x &&
         int64_t(y) + h <= int64_t(l.height) + b.y && int64_t(z) + d <= int64_t(l.depth) + b.z;
}

Texture::Level Context::next_level_with_border(const Texture::Level& above, bool volume, bool one_d) {
  // The image inside the ring, its next level, and a ring of that level's edge texels.
  const size_t stride = size_t(above.width) + 2, rows = size_t(above.height) + 2;
  Texture::Level image{above.width, above.height, {}, above.depth};
  image.texels.reserve(size_t(above.width) * above.height * above.depth);
  for (int z = 0; z < above.depth; ++z)
    for (int y = 0; y < above.height; ++y)
      for (int x = 0; x < above.width; ++x)
        image.texels.push_back(above.texels[(size_t(z + (volume ? 1 : 0)) * rows + size_t(y + 1)) * stride + size_t(x + 1)]);
  const Texture::Level next = next_mip_level(image);
  Texture::Level out{next.width, next.height, {}, next.depth, 1};
  const int slices = next.depth + (volume ? 2 : 0);
  out.texels.resize(size_t(next.width + 2) * size_t(next.height + 2) * size_t(slices));
  for (int z = 0; z < slices; ++z)
    for (int y = 0; y < next.height + 2; ++y)
      for (int x = 0; x < next.width + 2; ++x) {
        const int sx = std::clamp(x - 1, 0, next.width - 1), sy = one_d ? 0 : std::clamp(y - 1, 0, next.height - 1);
        const int sz = volume ? std::clamp(z - 1, 0, next.depth - 1) : z;
        out.texels[(size_t(z) * size_t(next.height + 2) + size_t(y)) * size_t(next.width + 2) + size_t(x)] =
            next.texels[(size_t(sz) * next.height + size_t(sy)) * next.width + size_t(sx)];
      }
  return out;
}

}  // namespace velocity::gl
