// The fill convention: every pixel centre covered by a closed mesh is drawn exactly once.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "raster/coverage.hpp"
#include "raster/setup.hpp"

using namespace velocity::raster;

namespace {

constexpr int W = 203, H = 137;  // not tile multiples, on purpose

// Rasterizes one triangle through the real set-up and span walk (tile by tile, as the
// renderer does) and adds 1 to every pixel it covers.
void rasterize_count(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, std::vector<int>& count) {
  TriangleSetup t;
  if (!setup_triangle(a, b, c, nullptr, nullptr, nullptr, 0, W, H, false, t)) return;
  for (int ty = 0; ty < H; ty += kTileSize)
    for (int tx = 0; tx < W; tx += kTileSize) {
      PixelRect tile{tx, ty, std::min(tx + kTileSize, W), std::min(ty + kTileSize, H)};
      for_each_span(t, tile, [&](int y, int x0, int x1) {
        for (int x = x0; x <= x1; ++x) count[size_t(y) * W + x]++;
      });
    }
}

ScreenVertex sv(float x, float y) { return ScreenVertex::make(x, y, 0.5f, 1.0f); }

}  // namespace

// A jittered grid of quads, each split into two triangles (alternating diagonals and
// windings), reaching past the screen on every side: each pixel exactly once.
TEST(FillRule, JitteredGridCoversEveryPixelExactlyOnce) {
  std::mt19937 rng(1234);
  for (int trial = 0; trial < 4; ++trial) {
    const int cols = 13 + trial * 7, rows = 9 + trial * 5;
    // Up to a quarter cell: every quad stays convex, so its two triangles never overlap.
    std::uniform_real_distribution<float> jitter(-0.25f, 0.25f);
    float cw = float(W + 20) / cols, ch = float(H + 20) / rows;
    std::vector<ScreenVertex> grid;
    for (int r = 0; r <= rows; ++r)
      for (int c = 0; c <= cols; ++c) {
        bool border = r == 0 || c == 0 || r == rows || c == cols;
        float jx = border ? 0 : jitter(rng) * cw, jy = border ? 0 : jitter(rng) * ch;
        // Some vertices land exactly on pixel centres and sub-pixel grid points.
        if (trial == 1 && !border) jx = std::round((c * cw - 10 + jx) * 2) / 2 - (c * cw - 10);
        grid.push_back(sv(-10 + c * cw + jx, -10 + r * ch + jy));
      }
    std::vector<int> count(size_t(W) * H, 0);
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) {
        const ScreenVertex& a = grid[size_t(r) * (cols + 1) + c];
        const ScreenVertex& b = grid[size_t(r) * (cols + 1) + c + 1];
        const ScreenVertex& d = grid[size_t(r + 1) * (cols + 1) + c];
        const ScreenVertex& e = grid[size_t(r + 1) * (cols + 1) + c + 1];
        if ((r + c) % 2) {
          rasterize_count(a, b, e, count);
          rasterize_count(a, e, d, count);
        } else {
          rasterize_count(a, d, b, count);  // the other winding
          rasterize_count(b, d, e, count);
        }
      }
    int zero = 0, many = 0;
    for (int n : count) zero += n == 0, many += n > 1;
    EXPECT_EQ(zero, 0) << "trial " << trial << ": pixels never drawn";
    EXPECT_EQ(many, 0) << "trial " << trial << ": pixels drawn more than once";
  }
}

// A fan around a centre on an exact pixel centre, with spokes through pixel centres.
TEST(FillRule, FanAroundSharedVertexIsWatertight) {
  const int spokes = 37;
  std::vector<ScreenVertex> rim;
  for (int i = 0; i < spokes; ++i) {
    float a = 2 * 3.14159265f * i / spokes;
    rim.push_back(sv(100.5f + 300 * std::cos(a), 68.5f + 300 * std::sin(a)));
  }
  std::vector<int> count(size_t(W) * H, 0);
  for (int i = 0; i < spokes; ++i) rasterize_count(sv(100.5f, 68.5f), rim[i], rim[(i + 1) % spokes], count);
  for (size_t i = 0; i < count.size(); ++i) ASSERT_EQ(count[i], 1) << "pixel " << i % W << "," << i / W;
}

// The span walk gives exactly the pixels the edge functions define, on random triangles.
TEST(FillRule, SpansMatchPerPixelEdgeFunctions) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> pos(-40.0f, 240.0f);
  for (int n = 0; n < 2000; ++n) {
    TriangleSetup t;
    if (!setup_triangle(sv(pos(rng), pos(rng)), sv(pos(rng), pos(rng)), sv(pos(rng), pos(rng)), nullptr, nullptr,
                        nullptr, 0, W, H, false, t))
      continue;
    std::vector<uint8_t> hit(size_t(W) * H, 0);
    for_each_span(t, PixelRect{0, 0, W, H}, [&](int y, int x0, int x1) {
      for (int x = x0; x <= x1; ++x) hit[size_t(y) * W + x]++;
    });
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) ASSERT_EQ(hit[size_t(y) * W + x], covers(t, x, y) ? 1 : 0) << x << "," << y;
  }
}

// Top-left rule on an axis-aligned square with edges exactly through pixel centres:
// the top and left rows are in, the bottom and right rows are out.
TEST(FillRule, TopLeftEdgesOwnTheirCentres) {
  std::vector<int> count(size_t(W) * H, 0);
  ScreenVertex a = sv(10.5f, 20.5f), b = sv(14.5f, 20.5f), c = sv(14.5f, 24.5f), d = sv(10.5f, 24.5f);
  rasterize_count(a, b, c, count);
  rasterize_count(a, c, d, count);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      bool inside = x >= 10 && x < 14 && y >= 20 && y < 24;
      ASSERT_EQ(count[size_t(y) * W + x], inside ? 1 : 0) << x << "," << y;
    }
}
