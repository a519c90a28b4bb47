// Textures: an RGBA8 image with its mip chain, and how it is sampled.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "velocity/image.hpp"

namespace velocity {

enum class Filter {
  Nearest,    // the texel under the sample point
  Bilinear,   // the four nearest texels, weighted (seed 000's "bi-linear interpolation")
  Trilinear,  // bilinear in the two nearest mip levels, blended by the level of detail
};
std::optional<Filter> parse_filter(std::string_view name);  // "nearest", "bilinear", "trilinear"

enum class Wrap {
  Repeat,          // u and v wrap around: 1.25 samples like 0.25
  Clamp,           // u and v are clamped to the edge texels (GL_CLAMP_TO_EDGE)
  ClampToBorder,   // texels outside the image read a border colour (GL_CLAMP_TO_BORDER)
  MirroredRepeat,  // every other repeat is mirrored (GL_MIRRORED_REPEAT)
  // OpenGL's GL_CLAMP: u and v clamped to [0, 1], then filtered with the border colour
  // outside the image: the edge texel for the nearest filter, half border at the edge
  // for the bilinear one.
  ClampHalfBorder,
};

class Texture {
 public:
  struct Level {
    int width, height;
    std::vector<uint32_t> texels;  // RGBA8, byte 0 red; row 0 is v = 0 (the image's top row)
    // A 3-D texture's levels (OpenGL's GL_TEXTURE_3D) are `depth` slices of width x
    // height texels one after another, slice 0 at r = 0; every other texture has 1.
    int depth = 1;
    // OpenGL's texture border (0 or 1): `texels` then hold the image with a ring of
    // border texels around it — (width + 2) x (height + 2), times depth + 2 slices for a
    // 3-D texture — and width, height and depth are the image's inside the ring. The
    // sampler reads the ring where clamp-to-border would read the border colour; the
    // other wrap modes never reach it.
    int border = 0;
  };

  // Builds the texture and its whole mip chain down to 1x1, each level the 2x2 box
  // average of the one above (odd sizes round down, as OpenGL's). Throws
  // velocity::Error for an empty image.
  explicit Texture(const Image& image);
  // A texture from levels the caller made (OpenGL's glTexImage2D per level): level 0
  // first, each next level max(1, size / 2) of the one above, as many as given (a
  // chain may stop before 1x1). Throws velocity::Error for no level, an empty level,
  // a size that does not halve, or a texel count that does not match the size. A 3-D
  // texture (`volume`: sampled with r too, whatever its depth) halves in depth too.
  // Every level has the same border.
  explicit Texture(std::vector<Level> levels, bool volume = false);

  int width() const { return levels_[0].width; }
  int height() const { return levels_[0].height; }
  int depth() const { return levels_[0].depth; }
  bool volume() const { return volume_; }  // a 3-D texture
  const std::vector<Level>& levels() const { return levels_; }
  // The levels' texels read as sRGB-encoded colours and decoded to linear light, 16
  // bits a channel (RGBA16, red in the low bits; alpha as it is, times 257): what a
  // linear frame's colour textures sample, so the kernels filter linear values and
  // decode none per texel. Made on the first call (thread-safe), kept with the texture
  // (and its copies) from then on: twice the memory of levels().
  const std::vector<std::vector<uint64_t>>& linear_levels() const;
  size_t memory_bytes() const;  // levels() only

 private:
  struct LinearCache;
  std::vector<Level> levels_;
  std::shared_ptr<LinearCache> linear_;
  bool volume_ = false;
};

// The mip level below `above`: max(1, size / 2) on each side, each texel the rounded
// average of the 2x2 block above it, per channel ((sum + 2) / 4); a side of 1 repeats
// its texel. OpenGL's box filter (Mesa's glGenerateMipmap): the one mip-map builder of
// Texture(const Image&), pGL's GL_GENERATE_MIPMAP and gluBuild2DMipmaps. A level of
// depth > 1 halves in depth too, each texel the average of a 2x2x2 block ((sum + 4) / 8;
// a side of 1 repeats its texels). `above` has no border (Level::border 0).
Texture::Level next_mip_level(const Texture::Level& above);

// Reads an image file as a texture: PCX by the extension, everything else through
// stb_image (PNG, JPEG, TGA, BMP, GIF). Throws velocity::Error naming the file.
std::shared_ptr<const Texture> load_texture(const std::string& path);

// The benchmark convention's default texture: 256x256, 32-texel squares, colours
// (230, 200, 80) and (40, 60, 160), starting with the latter at texel (0, 0).
Image make_checkerboard(int size = 256, int square = 32);

// A sphere environment map (as seen in a mirror ball) of a studio: a bright sky
// gradient above the horizon, a darker floor below, and two soft lights.
Image make_environment_map(int size = 256);

}  // namespace velocity
