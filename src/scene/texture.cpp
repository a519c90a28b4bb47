#include "velocity/texture.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>

#include "core/srgb.hpp"
#include "velocity/error.hpp"
#include "velocity/pcx.hpp"

namespace velocity {

std::optional<Filter> parse_filter(std::string_view name) {
  if (name == "nearest") return Filter::Nearest;
  if (name == "bilinear") return Filter::Bilinear;
  if (name == "trilinear") return Filter::Trilinear;
  return std::nullopt;
}

struct Texture::LinearCache {
  std::once_flag once;
  std::vector<std::vector<uint64_t>> levels;
};

Texture::Texture(const Image& image) : linear_(std::make_shared<LinearCache>()) {
  if (image.width <= 0 || image.height <= 0 || image.pixels.size() != size_t(image.width) * image.height * 4)
    throw Error("texture: the image is empty or inconsistent");
  Level base{image.width, image.height, std::vector<uint32_t>(size_t(image.width) * image.height)};
  std::memcpy(base.texels.data(), image.pixels.data(), image.pixels.size());
  levels_.push_back(std::move(base));
  while (levels_.back().width > 1 || levels_.back().height > 1) levels_.push_back(next_mip_level(levels_.back()));
}

Texture::Level next_mip_level(const Texture::Level& up) {
  const int w = std::max(1, up.width / 2), h = std::max(1, up.height / 2), d = up.depth > 1 ? up.depth / 2 : 1;
  Texture::Level next{w, h, std::vector<uint32_t>(size_t(w) * h * d), d};
  // The 2x2 (2x2x2) block above: a 1-texel-wide side repeats its one texel.
  const int slices = up.depth > 1 ? 2 : 1;
  const size_t plane = size_t(up.width) * up.height;
  for (int z = 0; z < d; ++z)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int x0 = std::min(2 * x, up.width - 1), x1 = std::min(2 * x + 1, up.width - 1);
        const int y0 = std::min(2 * y, up.height - 1), y1 = std::min(2 * y + 1, up.height - 1);
        uint32_t sum[4] = {0, 0, 0, 0};
        for (int k = 0; k < slices; ++k) {
          const uint32_t* s = up.texels.data() + size_t(std::min(2 * z + k, up.depth - 1)) * plane;
          for (uint32_t v : {s[size_t(y0) * up.width + x0], s[size_t(y0) * up.width + x1], s[size_t(y1) * up.width + x0],
                             s[size_t(y1) * up.width + x1]})
            for (int c = 0; c < 4; ++c) sum[c] += (v >> (8 * c)) & 0xff;
        }
        const uint32_t n = 4u * uint32_t(slices);
        uint32_t out = 0;
        for (int c = 0; c < 4; ++c) out |= ((sum[c] + n / 2) / n) << (8 * c);
        next.texels[(size_t(z) * h + y) * w + x] = out;
      }
  return next;
}

Texture::Texture(std::vector<Level> levels, bool volume)
    : levels_(std::move(levels)), linear_(std::make_shared<LinearCache>()), volume_(volume) {
  if (levels_.empty()) throw Error("texture: no levels");
  if (!volume_ && levels_[0].depth != 1) throw Error("texture: a 2-D texture with slices");
  const int b = levels_[0].border;
  if (b != 0 && b != 1) throw Error("texture: a border of " + std::to_string(b) + " texels (0 or 1)");
  for (size_t i = 0; i < levels_.size(); ++i) {
    const Level& l = levels_[i];
    if (l.border != b) throw Error("texture: level " + std::to_string(i) + " has another border than level 0");
    const size_t slices = size_t(l.depth) + (volume_ ? 2 * size_t(b) : 0);
    if (l.width <= 0 || l.height <= 0 || l.depth <= 0 || l.width > 65536 || l.height > 65536 || l.depth > 65536 ||
        l.texels.size() != size_t(l.width + 2 * b) * size_t(l.height + 2 * b) * slices)
      throw Error("texture: level " + std::to_string(i) + " is empty or its texels do not match its size");
    if (i > 0 && (l.width != std::max(1, levels_[i - 1].width / 2) || l.height != std::max(1, levels_[i - 1].height / 2) ||
                  l.depth != std::max(1, levels_[i - 1].depth / 2)))
      throw Error("texture: level " + std::to_string(i) + " is not half the size of the level above");
  }
}

const std::vector<std::vector<uint64_t>>& Texture::linear_levels() const {
  std::call_once(linear_->once, [this] {
    // Each level decoded as it is (the chain was averaged in sRGB, as OpenGL's is).
    uint64_t decode[256];
    for (int i = 0; i < 256; ++i) decode[i] = uint64_t(std::lround(65535.0f * color::srgb_to_linear(float(i) / 255.0f)));
    for (const Level& l : levels_) {
      std::vector<uint64_t> out(l.texels.size());
      for (size_t i = 0; i < out.size(); ++i) {
        const uint32_t t = l.texels[i];
        out[i] = decode[t & 0xff] | decode[(t >> 8) & 0xff] << 16 | decode[(t >> 16) & 0xff] << 32 |
                 uint64_t(t >> 24) * 257 << 48;
      }
      linear_->levels.push_back(std::move(out));
    }
  });
  return linear_->levels;
}

size_t Texture::memory_bytes() const {
  size_t n = 0;
  for (const Level& l : levels_) n += l.texels.size() * 4;
  return n;
}

std::shared_ptr<const Texture> load_texture(const std::string& path) {
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return std::make_shared<const Texture>(ext == ".pcx" ? read_pcx(path) : read_image(path));
}

Image make_checkerboard(int size, int square) {
  Image img(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      bool light = ((x / square) ^ (y / square)) & 1;
      uint8_t* p = img.pixel(x, y);
      p[0] = light ? 230 : 40, p[1] = light ? 200 : 60, p[2] = light ? 80 : 160, p[3] = 255;
    }
  return img;
}

Image make_environment_map(int size) {
  Image img(size, size);
  auto smooth = [](float e0, float e1, float x) {
    float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3 - 2 * t);
  };
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      // The texel's normal on the mirror ball: (nx, ny) from its position, v = 0 is the
      // top row, which the convention maps to ny = 1 (v = 0.5 - 0.5 ny).
      float nx = (x + 0.5f) / size * 2 - 1, ny = 1 - (y + 0.5f) / size * 2;
      float r2 = nx * nx + ny * ny;
      float nz = std::sqrt(std::max(0.0f, 1 - r2));
      // Reflect the view direction (0, 0, -1) about n: the direction the mirror shows.
      float rx = 2 * nz * nx, ry = 2 * nz * ny, rz = 2 * nz * nz - 1;
      float sky = smooth(-0.05f, 0.3f, ry);
      float r = 0.25f + 0.2f * sky, g = 0.22f + 0.35f * sky, b = 0.2f + 0.65f * sky;
      // The floor: a warm grey with a faint grid.
      if (ry < 0) {
        float gx = std::fabs(std::fmod(rx / std::min(-ry, -0.05f) * 2, 1.0f)), gz = std::fabs(std::fmod(rz / std::min(-ry, -0.05f) * 2, 1.0f));
        float line = (gx < 0.06f || gz < 0.06f) ? 0.1f : 0.0f;
        r += line, g += line, b += line;
      }
      // Two soft lights, up left and up right.
      auto spot = [&](float lx, float ly, float lz) {
        float d = rx * lx + ry * ly + rz * lz;
        return std::pow(std::max(d, 0.0f), 60.0f) * 1.5f;
      };
      float s = spot(-0.5f, 0.7f, 0.5f) + spot(0.6f, 0.6f, 0.53f);
      if (r2 > 1) r = g = b = 0.05f, s = 0;
      uint8_t* p = img.pixel(x, y);
      p[0] = uint8_t(std::clamp(r + s, 0.0f, 1.0f) * 255), p[1] = uint8_t(std::clamp(g + s, 0.0f, 1.0f) * 255);
      p[2] = uint8_t(std::clamp(b + s, 0.0f, 1.0f) * 255), p[3] = 255;
    }
  return img;
}

}  // namespace velocity
