#include "compare.hpp"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace vref {
namespace {

constexpr int kDiffGain = 4;

void check_same_size(const Image& a, const Image& b) {
  for (const Image* img : {&a, &b})
    if (img->width < 0 || img->height < 0 || img->rgba.size() != size_t(img->width) * img->height * 4)
      throw std::invalid_argument("image pixel data does not match its size");
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
}

// Largest absolute RGB difference of pixel p.
int pixel_diff(const Image& a, const Image& b, size_t p) {
  int largest = 0;
  for (size_t c = 0; c < 3; ++c) largest = std::max(largest, std::abs(int(a.rgba[4 * p + c]) - int(b.rgba[4 * p + c])));
  return largest;
}

}  // namespace

Diff compare(const Image& a, const Image& b, int tol) {
  check_same_size(a, b);
  const size_t pixels = size_t(a.width) * a.height;
  Diff d;
  if (pixels == 0) return d;
  double squared = 0, sum = 0;
  size_t over = 0;
  for (size_t p = 0; p < pixels; ++p) {
    for (size_t c = 0; c < 3; ++c) {
      const int e = std::abs(int(a.rgba[4 * p + c]) - int(b.rgba[4 * p + c]));
      squared += double(e) * e;
      sum += e;
    }
    const int largest = pixel_diff(a, b, p);
    d.max_abs = std::max(d.max_abs, largest);
    if (largest > tol) ++over;
  }
  const double samples = 3.0 * double(pixels);
  const double mse = squared / samples;
  d.psnr = mse == 0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
  d.mean_abs = sum / samples;
  d.over_tol_fraction = double(over) / double(pixels);
  return d;
}

void write_png(const std::string& path, const Image& image) {
  if (image.width < 1 || image.height < 1 || image.rgba.size() != size_t(image.width) * image.height * 4)
    throw std::invalid_argument("cannot write '" + path + "': empty or inconsistent image");
  if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw std::runtime_error("cannot write PNG '" + path + "'");
}

Image diff_image(const Image& a, const Image& b) {
  check_same_size(a, b);
  Image out{a.width, a.height, std::vector<uint8_t>(a.rgba.size())};
  for (size_t p = 0; p < size_t(a.width) * a.height; ++p) {
    const auto level = uint8_t(std::min(255, kDiffGain * pixel_diff(a, b, p)));
    out.rgba[4 * p] = out.rgba[4 * p + 1] = out.rgba[4 * p + 2] = level;
    out.rgba[4 * p + 3] = 255;
  }
  return out;
}

}  // namespace vref
