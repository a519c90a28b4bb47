#include "raster/bins.hpp"

#include <algorithm>

namespace velocity::raster {

void Bins::resize(int width, int height) {
  const int tiles_x = (width + kTileSize - 1) / kTileSize, tiles_y = (height + kTileSize - 1) / kTileSize;
  lists_.resize(size_t(tiles_x) * tiles_y);  // if this throws, nothing has changed
  width_ = width, height_ = height;
  tiles_x_ = tiles_x, tiles_y_ = tiles_y;
  clear();
}

void Bins::clear() {
  for (auto& l : lists_) l.clear();
}

PixelRect Bins::rect(int tile) const {
  int tx = tile % tiles_x_, ty = tile / tiles_x_;
  int x0 = tx * kTileSize, y0 = ty * kTileSize;
  return {x0, y0, std::min(x0 + kTileSize, width_), std::min(y0 + kTileSize, height_)};
}

}  // namespace velocity::raster
