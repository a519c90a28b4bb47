// The pixel centres a small triangle covers (set-up's fast path, setup.cpp).
#pragma once

#include <cstdint>

#include "raster/contract.hpp"

namespace velocity::triangle {

// The three edge functions of a triangle at the first centre of its box, and their
// steps one centre right and one centre down; every value over the box fits int32.
struct SmallEdges {
  int32_t row_start[3], step_x[3], step_y[3];
};

// Bit y * kSmallSide + x is set when centre (x, y) of the box (x < columns <= 8,
// y < rows <= 8) has all three edge functions >= 0.
uint64_t small_coverage(const SmallEdges& edges, int columns, int rows);

}  // namespace velocity::triangle
