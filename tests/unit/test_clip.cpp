// Region codes and homogeneous clipping.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "triangle/clip.hpp"

using namespace velocity;
using namespace velocity::geometry;
using namespace velocity::triangle;

namespace {

ClipVertex cv(float x, float y, float z, float w, float v0 = 0) {
  ClipVertex c{};
  c.pos = {x, y, z, w};
  c.var[0] = v0;
  return c;
}

const GuardBand kGuard = GuardBand::for_viewport(640, 360);

}  // namespace

TEST(Clip, OutcodesNameThePlanes) {
  EXPECT_EQ(outcode({0, 0, 0, 1}, kGuard), 0u);
  EXPECT_EQ(outcode({-2, 0, 0, 1}, kGuard), uint32_t(kOutLeft));
  EXPECT_EQ(outcode({0, 2, 0, 1}, kGuard), uint32_t(kOutTop));
  EXPECT_EQ(outcode({0, 0, -2, 1}, kGuard), uint32_t(kOutNear));
  EXPECT_EQ(outcode({0, 0, 2, 1}, kGuard), uint32_t(kOutFar));
  EXPECT_EQ(outcode({1e6f, 0, 0, 1}, kGuard), uint32_t(kOutRight | kOutGuardRight));
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(outcode({nan, 0, 0, 1}, kGuard), uint32_t(kOutNonFinite));
  EXPECT_EQ(outcode({0, 0, 0, inf}, kGuard), uint32_t(kOutNonFinite));
}

// One vertex in front of the near plane, two behind it: the triangle becomes a smaller
// triangle; two in front: a quad (two triangles after the fan).
TEST(Clip, TriangleCrossingNearPlane) {
  ClipVertex p[kMaxClippedVertices] = {cv(0, 0, 0, 1, 0), cv(1, 0, -3, 1, 1), cv(0, 1, -3, 1, 2)};
  int n = clip_polygon(p, 3, kOutNear, kGuard, 1);
  ASSERT_EQ(n, 3);
  for (int i = 0; i < n; ++i) EXPECT_GE(p[i].pos.z, -p[i].pos.w - 1e-6f);
  // The new vertex on the edge 0-1 sits at t = 1/3 of the way: its varying is 1/3.
  EXPECT_NEAR(p[1].var[0], 1.0f / 3.0f, 1e-6f);

  ClipVertex q[kMaxClippedVertices] = {cv(0, 0, 0, 1), cv(1, 0, 0, 1), cv(0, 1, -3, 1)};
  EXPECT_EQ(clip_polygon(q, 3, kOutNear, kGuard, 0), 4);
}

// A vertex behind the eye (w < 0): what is left lies entirely in front of the near plane.
TEST(Clip, VertexBehindTheEye) {
  ClipVertex p[kMaxClippedVertices] = {cv(0, 0, 0.5f, 1), cv(0.5f, 0, 0.5f, 1), cv(0, 0.5f, 3, -2)};
  int n = clip_polygon(p, 3, kOutNear | kOutFar, kGuard, 0);
  ASSERT_EQ(n, 4);
  for (int i = 0; i < n; ++i) {
    EXPECT_GT(p[i].pos.w, 0.0f);
    EXPECT_GE(p[i].pos.z, -p[i].pos.w - 1e-5f);
    EXPECT_LE(p[i].pos.z, p[i].pos.w + 1e-5f);
  }
}

// Far outside the guard band: clipped to it, so snapped coordinates cannot overflow.
TEST(Clip, TriangleFarOutsideGuardBand) {
  ClipVertex p[kMaxClippedVertices] = {cv(-1e7f, -1e7f, 0, 1), cv(1e7f, -1e7f, 0, 1), cv(0, 1e7f, 0, 1)};
  uint32_t codes = outcode(p[0].pos, kGuard) | outcode(p[1].pos, kGuard) | outcode(p[2].pos, kGuard);
  int n = clip_polygon(p, 3, codes, kGuard, 0);
  ASSERT_GE(n, 3);
  for (int i = 0; i < n; ++i) {
    EXPECT_LE(std::fabs(p[i].pos.x), kGuard.x * p[i].pos.w * 1.0001f);
    EXPECT_LE(std::fabs(p[i].pos.y), kGuard.y * p[i].pos.w * 1.0001f);
  }
}

TEST(Clip, EverythingOutsideLeavesNothing) {
  ClipVertex p[kMaxClippedVertices] = {cv(0, 0, -5, 1), cv(1, 0, -5, 1), cv(0, 1, -5, 1)};
  EXPECT_EQ(clip_polygon(p, 3, kOutNear, kGuard, 0), 0);
}

TEST(Clip, LineAgainstNearPlane) {
  Vec4 a{0, 0, -3, 1}, b{0, 0, 0.5f, 1};
  ASSERT_TRUE(clip_line(a, b, kOutNear, kGuard));
  EXPECT_NEAR(a.z, -1.0f, 1e-6f);
  EXPECT_EQ(b.z, 0.5f);
  Vec4 c{0, 0, -3, 1}, d{0, 0, -2, 1};
  EXPECT_FALSE(clip_line(c, d, kOutNear, kGuard));
}
