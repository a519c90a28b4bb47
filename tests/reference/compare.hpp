// Image comparison for the golden-image tests: the same figures as the reference
// tools' imgdiff (PSNR over RGB, channel differences, share of pixels off by more
// than a tolerance), plus PNG output of an image and of a visual diff.
#pragma once

#include "reference.hpp"

#include <string>

namespace vref {

struct Diff {
  double psnr = 99.0;               // dB over RGB; 99 when the images are identical
  double mean_abs = 0.0;            // mean absolute channel difference (RGB, 0..255)
  int max_abs = 0;                  // largest absolute channel difference
  double over_tol_fraction = 0.0;   // share of pixels (0..1) whose largest channel difference > tol
};

// Compares the RGB channels (alpha is ignored). Throws std::invalid_argument if the
// sizes differ or an image's pixel data does not match its size.
Diff compare(const Image& a, const Image& b, int tol = 8);

// Writes an RGBA PNG. Throws std::runtime_error on failure.
void write_png(const std::string& path, const Image& image);

// Grey image of each pixel's largest RGB difference times 4 (clamped), so that the
// one-level differences stay faint and real errors stand out. Throws as compare().
Image diff_image(const Image& a, const Image& b);

}  // namespace vref
