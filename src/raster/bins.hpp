// Binning: each primitive's command goes to the list of every 64x64 tile its bounding
// box touches. Tiles are then rasterised independently, each reading only its own list,
// which is what lets them run on separate cores.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/coverage.hpp"
#include "raster/raster_types.hpp"

namespace velocity::raster {

class Bins {
 public:
  // Sizes the tile grid for a width x height framebuffer; keeps the lists' storage.
  void resize(int width, int height);
  // Empties every list without freeing memory: no allocation per frame in steady state.
  void clear();
  // Adds `command` to every tile that the inclusive pixel box touches.
  void add(uint32_t command, int min_x, int min_y, int max_x, int max_y) {
    int tx0 = min_x >> kTileSizeLog2, tx1 = max_x >> kTileSizeLog2;
    int ty0 = min_y >> kTileSizeLog2, ty1 = max_y >> kTileSizeLog2;
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) lists_[size_t(ty) * tiles_x_ + tx].push_back(command);
  }

  int tiles_x() const { return tiles_x_; }
  int tiles_y() const { return tiles_y_; }
  int tile_count() const { return tiles_x_ * tiles_y_; }
  const std::vector<uint32_t>& commands(int tile) const { return lists_[tile]; }
  PixelRect rect(int tile) const;

 private:
  int width_ = 0, height_ = 0, tiles_x_ = 0, tiles_y_ = 0;
  std::vector<std::vector<uint32_t>> lists_;
};

}  // namespace velocity::raster
