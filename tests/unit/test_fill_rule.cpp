// The fill convention: every pixel centre covered by a closed mesh is drawn exactly once.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "raster/rasterize.hpp"
#include "triangle/setup.hpp"
#include "triangle/cull.hpp"

using namespace velocity::raster;
using namespace velocity::triangle;

namespace {

constexpr int W = 203, H = 137;  // not tile multiples, on purpose

velocity::geometry::SetupParams screen_box() {
  velocity::geometry::SetupParams p;
  p.x1 = p.px1 = W - 1;
  p.y1 = p.py1 = H - 1;
  return p;
}

// A worker's bins with a pool of their own.
struct TestBins {
  BlockPool pool;
  WorkerBins bins;
  TestBins() {
    bins.attach(&pool);
    bins.resize(1, 1);
  }
};

// Sets up one triangle through the real set-up; null when it covers no pixel centre.
const RecordHeader* setup(TestBins& t, const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
  t.pool.reset(0);
  t.bins.clear();
  uint32_t offset;
  return setup_triangle(t.bins, a, b, c, nullptr, nullptr, nullptr, 0, RecordInfo{}, screen_box(), offset);
}

// Calls f(x, y) for every pixel the renderer's coverage (hierarchical, SIMD) gives the
// record, tile by tile as the renderer walks it; `depth_only`: as a depth-only draw (a
// shadow map's caster) walks it.
template <class F>
void for_each_covered(const RecordHeader& r, F&& f, bool depth_only = false) {
  for (int ty = 0; ty < H; ty += velocity::kTileSize)
    for (int tx = 0; tx < W; tx += velocity::kTileSize)
      coverage_for_test(r, tx, ty, std::min(velocity::kTileSize, W - tx), std::min(velocity::kTileSize, H - ty),
                        [](void* user, int x, int y, uint32_t mask) {
                          for (int k = 0; k < 16; ++k)
                            if (mask >> k & 1) (*static_cast<F*>(user))(x + (k & 3), y + (k >> 2));
                        },
                        &f, depth_only);
}

// Rasterizes one triangle and adds 1 to every pixel it covers.
void rasterize_count(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, std::vector<int>& count,
                     bool depth_only = false) {
  TestBins bins;
  const RecordHeader* r = setup(bins, a, b, c);
  if (!r) return;
  for_each_covered(*r, [&](int x, int y) { count[size_t(y) * W + x]++; }, depth_only);
}

// The per-pixel definition of coverage, from the snapped vertices alone (not from
// anything set-up made): the triangle wound positively, all three edge functions
// E_i(p) = (p - v_i) x (v_{i+1} - v_i) >= 0 at the pixel centre, with 1 taken off
// those of edges that are neither top nor left.
bool covers(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int x, int y) {
  int64_t X[3] = {a.fx, b.fx, c.fx}, Y[3] = {a.fy, b.fy, c.fy};
  const int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
  if (area == 0) return false;
  if (area < 0) std::swap(X[1], X[2]), std::swap(Y[1], Y[2]);
  const int64_t px = int64_t(x) * kSubpixelOne + kSubpixelHalf, py = int64_t(y) * kSubpixelOne + kSubpixelHalf;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const int64_t dx = X[j] - X[i], dy = Y[j] - Y[i];
    int64_t e = -dy * (px - X[i]) + dx * (py - Y[i]);
    if (!(dy < 0 || (dy == 0 && dx > 0))) e -= 1;
    if (e < 0) return false;
  }
  return true;
}

ScreenVertex sv(float x, float y) { return ScreenVertex::make(x, y, 0.5f, 1.0f); }

}  // namespace

// A jittered grid of quads, each split into two triangles (alternating diagonals and
// windings), reaching past the screen on every side: each pixel exactly once, in the
// colour pass's coverage (trials 0-3) and a depth-only draw's (4-7).
TEST(FillRule, JitteredGridCoversEveryPixelExactlyOnce) {
  std::mt19937 rng(1234);
  for (int run = 0; run < 8; ++run) {
    const int trial = run % 4;
    const bool depth_only = run >= 4;
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
          rasterize_count(a, b, e, count, depth_only);
          rasterize_count(a, e, d, count, depth_only);
        } else {
          rasterize_count(a, d, b, count, depth_only);  // the other winding
          rasterize_count(b, d, e, count, depth_only);
        }
      }
    int zero = 0, many = 0;
    for (int n : count) zero += n == 0, many += n > 1;
    EXPECT_EQ(zero, 0) << "run " << run << ": pixels never drawn";
    EXPECT_EQ(many, 0) << "run " << run << ": pixels drawn more than once";
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

// The hierarchical coverage gives exactly the pixels the edge functions define, on
// random triangles of every size (from a fraction of a pixel to several tiles) and
// random positions, including ones set up as "no pixel covered". Also the guard band's
// largest coefficients.
TEST(FillRule, CoverageMatchesPerPixelEdgeFunctions) {
  std::mt19937 rng(99);
  TestBins bins;
  int drawn = 0;
  for (int n = 0; n < 8000; ++n) {
    // Large (the 16x16 and 4x4 block classification), under 128 pixels a side (covered
    // row by row without it), under 16, under 16 but past the 8x8 of the small ones,
    // and small.
    const float size = n % 5 == 0 ? 300.0f : n % 5 == 1 ? 50.0f : n % 5 == 2 ? 12.0f : n % 5 == 3 ? 7.0f : 2.5f;
    std::uniform_real_distribution<float> centre(-20.0f, 220.0f), off(-size, size);
    const float cx = centre(rng), cy = centre(rng);
    const ScreenVertex a = sv(cx + off(rng), cy + off(rng)), b = sv(cx + off(rng), cy + off(rng)), c = sv(cx + off(rng), cy + off(rng));
    const RecordHeader* r = setup(bins, a, b, c);
    if (!r) continue;  // DroppedSmallTrianglesCoverNothing checks these
    // The colour pass's coverage, then a depth-only draw's (which skips the blocks an
    // edge excludes whole in each row).
    for (bool depth_only : {false, true}) {
      std::vector<uint8_t> hit(size_t(W) * H, 0);
      for_each_covered(*r, [&](int x, int y) { hit[size_t(y) * W + x]++; }, depth_only);
      // Every pixel of the image, not only the record's box: the box must not lose any.
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
          ASSERT_EQ(hit[size_t(y) * W + x], covers(a, b, c, x, y) ? 1 : 0)
              << "triangle " << n << (depth_only ? " (depth only)" : "") << " pixel " << x << "," << y;
    }
    ++drawn;
  }
  EXPECT_GT(drawn, 4000);
}

// The set-up's "covers no pixel centre" verdict for small triangles is exact: every
// triangle it drops covers no centre by the per-pixel definition.
TEST(FillRule, DroppedSmallTrianglesCoverNothing) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> centre(0.0f, 200.0f), off(-1.2f, 1.2f);
  int dropped = 0;
  for (int n = 0; n < 20000; ++n) {
    const float cx = centre(rng), cy = centre(rng);
    ScreenVertex v[3] = {sv(cx + off(rng), cy + off(rng)), sv(cx + off(rng), cy + off(rng)), sv(cx + off(rng), cy + off(rng))};
    TestBins bins;
    if (setup(bins, v[0], v[1], v[2])) continue;
    ++dropped;
    // The exact definition, evaluated here from the snapped vertices.
    int64_t X[3], Y[3];
    for (int i = 0; i < 3; ++i) X[i] = v[i].fx, Y[i] = v[i].fy;
    int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
    if (area == 0) continue;
    if (area < 0) std::swap(X[1], X[2]), std::swap(Y[1], Y[2]);
    for (int y = int(cy) - 3; y <= int(cy) + 3; ++y)
      for (int x = int(cx) - 3; x <= int(cx) + 3; ++x) {
        if (x < 0 || y < 0 || x >= W || y >= H) continue;
        const int64_t px = int64_t(x) * 256 + 128, py = int64_t(y) * 256 + 128;
        bool in = true;
        for (int i = 0; i < 3 && in; ++i) {
          const int j = (i + 1) % 3;
          const int64_t dx = X[j] - X[i], dy = Y[j] - Y[i];
          int64_t e = -dy * px + dx * py + (dy * X[i] - dx * Y[i]);
          if (!(dy < 0 || (dy == 0 && dx > 0))) e -= 1;
          in = e >= 0;
        }
        ASSERT_FALSE(in) << "a dropped triangle covers pixel " << x << "," << y;
      }
  }
  EXPECT_GT(dropped, 1000);
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

// The triangle stage's first pass (N triangles at a time) against the exact per-pixel
// definition: what it drops covers no pixel centre (or faces away), and the pixels it
// hands on for small triangles are exactly the covered ones.
TEST(FillRule, FirstPassIsExact) {
  using namespace velocity::geometry;
  std::mt19937 rng(2024);
  const int n = 20000;
  std::vector<ProjectedVertex> pv;
  std::vector<uint32_t> codes;
  std::vector<velocity::Triangle> tris;
  std::uniform_real_distribution<float> centre(-3.0f, 206.0f);
  for (int t = 0; t < n; ++t) {
    const float size = t % 4 == 0 ? 6.0f : t % 4 == 1 ? 3.0f : 1.5f;
    std::uniform_real_distribution<float> off(-size, size);
    const float cx = centre(rng), cy = centre(rng);
    for (int k = 0; k < 3; ++k) {
      const ScreenVertex v = sv(cx + off(rng), cy + off(rng));
      pv.push_back({v.fx, v.fy, 0.5f, 1.0f});
      codes.push_back(0);
    }
    tris.push_back({{uint32_t(3 * t), uint32_t(3 * t + 1), uint32_t(3 * t + 2)}});
  }
  CullJob job;
  job.triangles = tris.data(), job.begin = 0, job.end = uint32_t(n);
  job.projected = pv.data(), job.codes = codes.data();
  job.cull_back = true, job.drop_empty = true;
  job.x0 = 0, job.y0 = 0, job.x1 = W - 1, job.y1 = H - 1;
  std::vector<uint32_t> direct(n), info(n), clip(n);
  size_t nd = 0, nc = 0;
  CullCounts counts;
  cull_triangles(job, direct.data(), info.data(), nd, clip.data(), nc, counts);
  EXPECT_EQ(nc, 0u);
  std::vector<uint32_t> learnt(n, UINT32_MAX);  // UINT32_MAX: dropped
  for (size_t i = 0; i < nd; ++i) learnt[direct[i]] = info[i];
  int small = 0;
  for (int t = 0; t < n; ++t) {
    ScreenVertex v[3];
    for (int k = 0; k < 3; ++k) {
      const ProjectedVertex& p = pv[size_t(3 * t + k)];
      v[k] = {float(p.fx) / 256, float(p.fy) / 256, 0.5f, 1.0f, p.fx, p.fy, true};
    }
    const bool front = facing(v[0], v[1], v[2]) == Facing::Front;
    // The exact answer: the pixel centres (on screen) a front face covers.
    std::vector<std::pair<int, int>> covered;
    if (front) {
      const int x0 = int(std::floor(std::min({v[0].x, v[1].x, v[2].x}))) - 1, x1 = int(std::max({v[0].x, v[1].x, v[2].x})) + 1;
      const int y0 = int(std::floor(std::min({v[0].y, v[1].y, v[2].y}))) - 1, y1 = int(std::max({v[0].y, v[1].y, v[2].y})) + 1;
      for (int y = std::max(y0, 0); y <= std::min(y1, H - 1); ++y)
        for (int x = std::max(x0, 0); x <= std::min(x1, W - 1); ++x)
          if (covers(v[0], v[1], v[2], x, y)) covered.emplace_back(x, y);
    }
    if (learnt[size_t(t)] == UINT32_MAX) {
      ASSERT_TRUE(covered.empty()) << "triangle " << t << " was dropped but covers " << covered.size() << " pixels";
      continue;
    }
    const uint32_t l = learnt[size_t(t)];
    if (!(l & kKnownSmall)) continue;  // handed on whole: set-up decides
    ++small;
    ASSERT_TRUE(l & kKnownFront) << t;
    // The mask is relative to the first centre of the triangle's box.
    int64_t minx = std::min({v[0].fx, v[1].fx, v[2].fx}), miny = std::min({v[0].fy, v[1].fy, v[2].fy});
    const int bx0 = std::max(0, int((minx + 127) >> 8)), by0 = std::max(0, int((miny + 127) >> 8));
    uint32_t expected = 0;
    for (auto [x, y] : covered) {
      ASSERT_TRUE(x - bx0 >= 0 && x - bx0 < 4 && y - by0 >= 0 && y - by0 < 4) << t;
      expected |= 1u << ((y - by0) * 4 + (x - bx0));
    }
    ASSERT_EQ(l & 0xffff, expected) << "triangle " << t;
  }
  EXPECT_GT(small, 2000);
  EXPECT_GT(counts.culled, 5000u);
}
