// Image files: PNG through stb_image_write, PPM by hand, reading through stb_image.
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "velocity/error.hpp"
#include "velocity/image.hpp"

namespace velocity {

Image::Image(int w, int h, uint32_t rgba) : width(w), height(h) {
  if (w <= 0 || h <= 0 || w > 65536 || h > 65536)
    throw Error("image size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range (1..65536 a side)");
  pixels.resize(size_t(w) * size_t(h) * 4);
  uint8_t c[4];
  std::memcpy(c, &rgba, 4);
  for (size_t i = 0; i < pixels.size(); i += 4) std::memcpy(&pixels[i], c, 4);
}

namespace {

std::string extension_of(const std::string& path) {
  auto dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return {};
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

void check_image(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.pixels.size() != size_t(image.width) * image.height * 4)
    throw Error(path + ": cannot write an empty or inconsistent image");
}

}  // namespace

void write_png(const std::string& path, const Image& image) {
  check_image(path, image);
  if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.pixels.data(), image.width * 4))
    throw Error(path + ": cannot write PNG (" + std::strerror(errno) + ")");
}

void write_ppm(const std::string& path, const Image& image) {
  check_image(path, image);
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!f) throw Error(path + ": cannot open for writing (" + std::strerror(errno) + ")");
  std::fprintf(f.get(), "P6\n%d %d\n255\n", image.width, image.height);
  std::vector<uint8_t> row(size_t(image.width) * 3);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) std::memcpy(&row[size_t(x) * 3], image.pixel(x, y), 3);
    if (std::fwrite(row.data(), 1, row.size(), f.get()) != row.size())
      throw Error(path + ": write failed (" + std::strerror(errno) + ")");
  }
  if (std::fflush(f.get()) != 0) throw Error(path + ": write failed (" + std::strerror(errno) + ")");
}

void write_image(const std::string& path, const Image& image) {
  std::string ext = extension_of(path);
  if (ext == "png") return write_png(path, image);
  if (ext == "ppm") return write_ppm(path, image);
  throw Error(path + ": unknown image extension '" + ext + "' (expected .png or .ppm)");
}

Image read_image(const std::string& path) {
  int w = 0, h = 0, n = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load(path.c_str(), &w, &h, &n, 4), &stbi_image_free);
  if (!data) throw Error(path + ": cannot read image (" + stbi_failure_reason() + ")");
  Image image(w, h);
  std::memcpy(image.pixels.data(), data.get(), image.pixels.size());
  return image;
}

}  // namespace velocity
