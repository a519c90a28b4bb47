// The teapot (glutSolidTeapot, glutWireTeapot): Martin Newell's Bezier patches, the
// public-domain data every GLUT has drawn, evaluated as freeglut 3 evaluates them — an
// 8x8 grid a patch for the solid (two triangles a cell, texture coordinates across the
// patch), 10x10 for the wire (line strips along both directions), normals from the two
// tangents, the quarter patches turned into the other three quadrants and the half
// patches (handle, spout) mirrored — so that the picture is freeglut's.
#include <GL/glut.h>

#include <cmath>
#include <limits>
#include <vector>

namespace {

// Ten patches of sixteen control points: rim, body (2), lid (2), bottom (turned into
// all four quadrants), handle (2), spout (2) (mirrored across the x-y plane).
const int kPatches[10][16] = {
    {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
    {12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27},
    {24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39},
    {40, 41, 42, 40, 43, 44, 45, 46, 47, 47, 47, 47, 48, 49, 50, 51},
    {48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63},
    {64, 64, 64, 64, 65, 66, 67, 68, 69, 70, 71, 72, 39, 38, 37, 36},
    {73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88},
    {85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100},
    {101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116},
    {113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128}};

// The control points, z up, 3.15 tall.
const float kPoints[][3] = {
    {1.4f, 0.0f, 2.4f}, {1.4f, -0.784f, 2.4f}, {0.784f, -1.4f, 2.4f}, {0.0f, -1.4f, 2.4f}, {1.3375f, 0.0f, 2.53125f},
    {1.3375f, -0.749f, 2.53125f}, {0.749f, -1.3375f, 2.53125f}, {0.0f, -1.3375f, 2.53125f},
    {1.4375f, 0.0f, 2.53125f}, {1.4375f, -0.805f, 2.53125f}, {0.805f, -1.4375f, 2.53125f},
    {0.0f, -1.4375f, 2.53125f}, {1.5f, 0.0f, 2.4f}, {1.5f, -0.84f, 2.4f}, {0.84f, -1.5f, 2.4f}, {0.0f, -1.5f, 2.4f},
    {1.75f, 0.0f, 1.875f}, {1.75f, -0.98f, 1.875f}, {0.98f, -1.75f, 1.875f}, {0.0f, -1.75f, 1.875f},
    {2.0f, 0.0f, 1.35f}, {2.0f, -1.12f, 1.35f}, {1.12f, -2.0f, 1.35f}, {0.0f, -2.0f, 1.35f}, {2.0f, 0.0f, 0.9f},
    {2.0f, -1.12f, 0.9f}, {1.12f, -2.0f, 0.9f}, {0.0f, -2.0f, 0.9f}, {2.0f, 0.0f, 0.45f}, {2.0f, -1.12f, 0.45f},
    {1.12f, -2.0f, 0.45f}, {0.0f, -2.0f, 0.45f}, {1.5f, 0.0f, 0.225f}, {1.5f, -0.84f, 0.225f},
    {0.84f, -1.5f, 0.225f}, {0.0f, -1.5f, 0.225f}, {1.5f, 0.0f, 0.15f}, {1.5f, -0.84f, 0.15f}, {0.84f, -1.5f, 0.15f},
    {0.0f, -1.5f, 0.15f}, {0.0f, 0.0f, 3.15f}, {0.0f, -0.002f, 3.15f}, {0.002f, 0.0f, 3.15f}, {0.8f, 0.0f, 3.15f},
    {0.8f, -0.45f, 3.15f}, {0.45f, -0.8f, 3.15f}, {0.0f, -0.8f, 3.15f}, {0.0f, 0.0f, 2.85f}, {0.2f, 0.0f, 2.7f},
    {0.2f, -0.112f, 2.7f}, {0.112f, -0.2f, 2.7f}, {0.0f, -0.2f, 2.7f}, {0.4f, 0.0f, 2.55f}, {0.4f, -0.224f, 2.55f},
    {0.224f, -0.4f, 2.55f}, {0.0f, -0.4f, 2.55f}, {1.3f, 0.0f, 2.55f}, {1.3f, -0.728f, 2.55f},
    {0.728f, -1.3f, 2.55f}, {0.0f, -1.3f, 2.55f}, {1.3f, 0.0f, 2.4f}, {1.3f, -0.728f, 2.4f}, {0.728f, -1.3f, 2.4f},
    {0.0f, -1.3f, 2.4f}, {0.0f, 0.0f, 0.0f}, {0.0f, -1.425f, 0.0f}, {0.798f, -1.425f, 0.0f}, {1.425f, -0.798f, 0.0f},
    {1.425f, 0.0f, 0.0f}, {0.0f, -1.5f, 0.075f}, {0.84f, -1.5f, 0.075f}, {1.5f, -0.84f, 0.075f},
    {1.5f, 0.0f, 0.075f}, {-1.6f, 0.0f, 2.025f}, {-1.6f, -0.3f, 2.025f}, {-1.5f, -0.3f, 2.25f}, {-1.5f, 0.0f, 2.25f},
    {-2.3f, 0.0f, 2.025f}, {-2.3f, -0.3f, 2.025f}, {-2.5f, -0.3f, 2.25f}, {-2.5f, 0.0f, 2.25f},
    {-2.7f, 0.0f, 2.025f}, {-2.7f, -0.3f, 2.025f}, {-3.0f, -0.3f, 2.25f}, {-3.0f, 0.0f, 2.25f}, {-2.7f, 0.0f, 1.8f},
    {-2.7f, -0.3f, 1.8f}, {-3.0f, -0.3f, 1.8f}, {-3.0f, 0.0f, 1.8f}, {-2.7f, 0.0f, 1.575f}, {-2.7f, -0.3f, 1.575f},
    {-3.0f, -0.3f, 1.35f}, {-3.0f, 0.0f, 1.35f}, {-2.5f, 0.0f, 1.125f}, {-2.5f, -0.3f, 1.125f},
    {-2.65f, -0.3f, 0.9375f}, {-2.65f, 0.0f, 0.9375f}, {-2.0f, 0.0f, 0.9f}, {-2.0f, -0.3f, 0.9f},
    {-1.9f, -0.3f, 0.6f}, {-1.9f, 0.0f, 0.6f}, {1.7f, 0.0f, 1.425f}, {1.7f, -0.66f, 1.425f}, {1.7f, -0.66f, 0.6f},
    {1.7f, 0.0f, 0.6f}, {2.6f, 0.0f, 1.425f}, {2.6f, -0.66f, 1.425f}, {3.1f, -0.66f, 0.825f}, {3.1f, 0.0f, 0.825f},
    {2.3f, 0.0f, 2.1f}, {2.3f, -0.25f, 2.1f}, {2.4f, -0.25f, 2.025f}, {2.4f, 0.0f, 2.025f}, {2.7f, 0.0f, 2.4f},
    {2.7f, -0.25f, 2.4f}, {3.3f, -0.25f, 2.4f}, {3.3f, 0.0f, 2.4f}, {2.8f, 0.0f, 2.475f}, {2.8f, -0.25f, 2.475f},
    {3.525f, -0.25f, 2.49375f}, {3.525f, 0.0f, 2.49375f}, {2.9f, 0.0f, 2.475f}, {2.9f, -0.15f, 2.475f},
    {3.45f, -0.15f, 2.5125f}, {3.45f, 0.0f, 2.5125f}, {2.8f, 0.0f, 2.4f}, {2.8f, -0.15f, 2.4f}, {3.2f, -0.15f, 2.4f},
    {3.2f, 0.0f, 2.4f},
};

// A cubic Bernstein basis at x and its derivative.
struct Basis {
  float b[4], d[4];
  explicit Basis(float x) {
    const float ix = 1.0f - x;
    b[0] = ix * ix * ix, d[0] = -3 * (ix * ix);
    b[1] = 3 * x * (ix * ix), d[1] = 3 * (ix * ix) - 6 * x * ix;
    b[2] = 3 * (x * x) * ix, d[2] = 6 * x * ix - 3 * (x * x);
    b[3] = x * (x * x), d[3] = 3 * (x * x);
  }
};

struct Grid {
  int n;                     // points a side of each patch
  std::vector<float> pos, nrm;  // 32 patches of n x n points, row after row
};

// One patch's n x n points and unit normals, appended to the grid; `pole` replaces the
// first row's normals (+1 up, -1 down) where the patch closes to a point (lid, bottom).
void evaluate(const float (&cp)[4][4][3], int n, int pole, Grid& g) {
  std::vector<Basis> basis;
  for (int s = 0; s < n; ++s) basis.emplace_back(float(s) / (float(n) - 1.0f));
  for (int u = 0; u < n; ++u)
    for (int v = 0; v < n; ++v) {
      float p[3] = {0, 0, 0}, t1[3] = {0, 0, 0}, t2[3] = {0, 0, 0};
      for (int i = 0; i < 4; ++i) {
        float row[3] = {0, 0, 0}, row_d[3] = {0, 0, 0};
        for (int j = 0; j < 4; ++j)
          for (int k = 0; k < 3; ++k) {
            row[k] += basis[size_t(v)].b[j] * cp[i][j][k];
            row_d[k] += basis[size_t(v)].d[j] * cp[i][j][k];
          }
        for (int k = 0; k < 3; ++k) {
          p[k] += basis[size_t(u)].b[i] * row[k];
          t1[k] += basis[size_t(u)].b[i] * row_d[k];
          t2[k] += basis[size_t(u)].d[i] * row[k];
        }
      }
      float nv[3] = {t1[1] * t2[2] - t1[2] * t2[1], t1[2] * t2[0] - t1[0] * t2[2], t1[0] * t2[1] - t1[1] * t2[0]};
      const float len = float(std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]));
      for (float& c : nv) c /= len;
      if (pole != 0 && u == 0) nv[0] = 0, nv[1] = float(pole), nv[2] = 0;
      g.pos.insert(g.pos.end(), p, p + 3);
      g.nrm.insert(g.nrm.end(), nv, nv + 3);
    }
}

// A patch's values (`count` floats from `first`) appended again, turned `quarter`
// quarter turns about y.
void turn(std::vector<float>& a, size_t first, size_t count, int quarter) {
  for (size_t o = first; o < first + count; o += 3) {
    const float x = a[o], y = a[o + 1], z = a[o + 2];
    const float t[3][3] = {{z, y, -x}, {-x, y, -z}, {-z, y, x}};
    a.insert(a.end(), t[quarter - 1], t[quarter - 1] + 3);
  }
}

// A patch appended again mirrored across the x-y plane, its rows in reverse order (so
// that its triangles keep their winding).
void mirror(std::vector<float>& a, size_t first, int n) {
  for (int u = n - 1; u >= 0; --u)
    for (int v = 0; v < n; ++v) {
      const size_t o = first + size_t((u * n + v) * 3);
      const float p[3] = {a[o], a[o + 1], -a[o + 2]};
      a.insert(a.end(), p, p + 3);
    }
}

Grid build(float scale, int n) {
  Grid g{n, {}, {}};
  for (int p = 0; p < 10; ++p) {
    // Stood up (y up), scaled by half the size, centred at 1.575 on the old z.
    float cp[4][4][3];
    for (int i = 0; i < 16; ++i) {
      const float* c = kPoints[kPatches[p][i]];
      cp[i / 4][i % 4][0] = c[0] * scale / 2.0f;
      cp[i / 4][i % 4][1] = (c[2] - 1.575f) * scale / 2.0f;
      cp[i / 4][i % 4][2] = -c[1] * scale / 2.0f;
    }
    const size_t first = g.pos.size(), count = size_t(n * n * 3);
    evaluate(cp, n, p == 3 ? 1 : p == 5 ? -1 : 0, g);
    if (p < 6) {
      for (int q = 1; q <= 3; ++q) turn(g.pos, first, count, q), turn(g.nrm, first, count, q);
    } else {
      mirror(g.pos, first, n), mirror(g.nrm, first, n);
    }
  }
  return g;
}

void put(const Grid& g, int k, bool texture) {
  const size_t o = size_t(k) * 3;
  if (texture) {
    const int local = k % (g.n * g.n);
    glTexCoord2f(float(local / g.n) / (float(g.n) - 1.0f), float(local % g.n) / (float(g.n) - 1.0f));
  }
  glNormal3f(g.nrm[o], g.nrm[o + 1], g.nrm[o + 2]);
  glVertex3f(g.pos[o], g.pos[o + 1], g.pos[o + 2]);
}

void teapot(double size, bool wire) {
  // freeglut computes in float: a size beyond float's range (or NaN) draws nothing.
  if (!(std::fabs(size) <= double(std::numeric_limits<float>::max()))) return;
  const int n = wire ? 10 : 8;
  const Grid g = build(float(size), n);
  const int patches = int(g.pos.size() / size_t(3 * n * n));
  if (wire) {
    for (int p = 0; p < patches; ++p)  // strips along u, then along v
      for (int c = 0; c < n; ++c) {
        glBegin(GL_LINE_STRIP);
        for (int r = 0; r < n; ++r) put(g, p * n * n + r * n + c, false);
        glEnd();
      }
    for (int p = 0; p < patches; ++p)
      for (int r = 0; r < n; ++r) {
        glBegin(GL_LINE_STRIP);
        for (int c = 0; c < n; ++c) put(g, p * n * n + r * n + c, false);
        glEnd();
      }
    return;
  }
  glBegin(GL_TRIANGLES);
  for (int p = 0; p < patches; ++p)
    for (int r = 0; r + 1 < n; ++r)
      for (int c = 0; c + 1 < n; ++c) {
        const int a = p * n * n + r * n + c, b = a + n;  // b: the next row
        for (int k : {a, b, b + 1, a, b + 1, a + 1}) put(g, k, true);
      }
  glEnd();
}

}  // namespace

extern "C" {

void glutSolidTeapot(double size) { teapot(size, false); }
void glutWireTeapot(double size) { teapot(size, true); }

}  // extern "C"
