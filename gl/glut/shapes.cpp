// GLUT's shapes (glutSolid*/glutWire*), drawn with pGL's glBegin/glNormal/glVertex as
// freeglut 3 builds them: the same vertices, normals and primitives (triangle strips
// for the round solids, face loops for the wire polyhedra), so that a GLUT program's
// picture is freeglut's. A count that freeglut draws nothing for draws nothing here.
// The teapot is not here yet (docs/gl.md).
#include <GL/glut.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

namespace {

struct Vec3 {
  float x, y, z;
};

// Mesh: positions and normals, one pair a vertex, drawn through lists of indices.
struct Mesh {
  std::vector<Vec3> pos, nrm;
  void add(Vec3 p, Vec3 n) { pos.push_back(p), nrm.push_back(n); }
  void draw(GLenum mode, const std::vector<int>& idx) const {
    glBegin(mode);
    for (int i : idx) {
      const Vec3& n = nrm[size_t(i)];
      const Vec3& p = pos[size_t(i)];
      glNormal3f(n.x, n.y, n.z);
      glVertex3f(p.x, p.y, p.z);
    }
    glEnd();
  }
};

// freeglut's circle table: n+1 samples of sin and cos from angle 0, n of them a turn
// (or half a turn), a negative n going the other way; the last equals the first (or is
// exactly pi's).
void circle(int n, bool half, std::vector<float>& s, std::vector<float>& c) {
  const int size = std::abs(n);
  const float step = (half ? 1.0f : 2.0f) * float(M_PI) / float(n == 0 ? 1 : n);
  s.assign(size_t(size) + 1, 0.0f), c.assign(size_t(size) + 1, 1.0f);
  for (int i = 1; i < size; ++i) {
    s[size_t(i)] = float(std::sin(double(step * float(i))));
    c[size_t(i)] = float(std::cos(double(step * float(i))));
  }
  if (half) s[size_t(size)] = 0.0f, c[size_t(size)] = -1.0f;
  else s[size_t(size)] = s[0], c[size_t(size)] = c[0];
}

// freeglut computes in float: a size beyond float's range (or NaN) draws nothing here
// rather than being converted (which C++ leaves undefined).
bool fits_float(double v) { return std::fabs(v) <= double(std::numeric_limits<float>::max()); }

// Counts beyond what 16-bit indices reach draw nothing (freeglut's indices wrap there).
bool too_many(long long vertices) { return vertices > 65535; }

void sphere(double radius, int slices, int stacks, bool wire) {
  if (slices <= 0 || stacks < 2 || too_many(1LL * slices * (stacks - 1) + 2) || !fits_float(radius)) return;
  std::vector<float> s1, c1, s2, c2;
  circle(-slices, false, s1, c1);
  circle(stacks, true, s2, c2);
  const float r = float(radius);
  Mesh m;
  m.add({0, 0, r}, {0, 0, 1});
  for (int i = 1; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      const Vec3 n{c1[size_t(j)] * s2[size_t(i)], s1[size_t(j)] * s2[size_t(i)], c2[size_t(i)]};
      m.add({n.x * r, n.y * r, n.z * r}, n);
    }
  m.add({0, 0, -r}, {0, 0, -1});
  const int last = int(m.pos.size()) - 1;
  const auto ring = [&](int i) { return 1 + i * slices; };  // first vertex of inner ring i
  if (wire) {
    for (int j = 0; j < slices; ++j) {  // meridians, pole to pole
      std::vector<int> idx{0};
      for (int i = 0; i < stacks - 1; ++i) idx.push_back(ring(i) + j);
      idx.push_back(last);
      m.draw(GL_LINE_STRIP, idx);
    }
    for (int i = 0; i < stacks - 1; ++i) {
      std::vector<int> idx;
      for (int j = 0; j < slices; ++j) idx.push_back(ring(i) + j);
      m.draw(GL_LINE_LOOP, idx);
    }
    return;
  }
  std::vector<int> idx;
  for (int j = 0; j <= slices; ++j) idx.push_back(1 + j % slices), idx.push_back(0);
  m.draw(GL_TRIANGLE_STRIP, idx);
  for (int i = 0; i < stacks - 2; ++i) {
    idx.clear();
    for (int j = 0; j <= slices; ++j) idx.push_back(ring(i + 1) + j % slices), idx.push_back(ring(i) + j % slices);
    m.draw(GL_TRIANGLE_STRIP, idx);
  }
  idx.clear();
  for (int j = 0; j <= slices; ++j) idx.push_back(last), idx.push_back(ring(stacks - 2) + j % slices);
  m.draw(GL_TRIANGLE_STRIP, idx);
}

void cone(double base, double height, int slices, int stacks, bool wire) {
  if (slices <= 0 || stacks < 1 || too_many(1LL * slices * (stacks + 2) + 1)) return;
  if (!fits_float(base) || !fits_float(height)) return;
  std::vector<float> s, c;
  circle(-slices, false, s, c);
  const float fb = float(base), fh = float(height);
  const float len = float(std::sqrt(double(fh * fh + fb * fb)));
  const float cosn = fh / len, sinn = fb / len;  // the side's slope: its normal leans up by sinn
  const float z_step = fh / float(stacks), r_step = fb / float(stacks);
  Mesh m;
  float z = 0, r = fb;
  m.add({0, 0, z}, {0, 0, -1});  // the base: its centre and rim, facing down
  for (int j = 0; j < slices; ++j) m.add({c[size_t(j)] * r, s[size_t(j)] * r, z}, {0, 0, -1});
  for (int i = 0; i <= stacks; ++i) {  // the side's rings, stepped as freeglut steps them
    for (int j = 0; j < slices; ++j)
      m.add({c[size_t(j)] * r, s[size_t(j)] * r, z}, {c[size_t(j)] * cosn, s[size_t(j)] * cosn, sinn});
    z += z_step, r -= r_step;
  }
  const auto ring = [&](int i) { return 1 + (i + 1) * slices; };  // side ring i
  if (wire) {
    std::vector<int> idx;
    for (int j = 0; j < slices; ++j) idx.push_back(ring(0) + j), idx.push_back(ring(stacks) + j);
    m.draw(GL_LINES, idx);
    for (int i = 0; i < stacks; ++i) {
      idx.clear();
      for (int j = 0; j < slices; ++j) idx.push_back(ring(i) + j);
      m.draw(GL_LINE_LOOP, idx);
    }
    return;
  }
  std::vector<int> idx;
  for (int j = 0; j <= slices; ++j) idx.push_back(0), idx.push_back(1 + j % slices);
  m.draw(GL_TRIANGLE_STRIP, idx);
  for (int i = 0; i < stacks; ++i) {
    idx.clear();
    for (int j = 0; j <= slices; ++j) idx.push_back(ring(i) + j % slices), idx.push_back(ring(i + 1) + j % slices);
    m.draw(GL_TRIANGLE_STRIP, idx);
  }
}

void torus(double inner, double outer, int sides, int rings, bool wire) {
  if (sides < 2 || rings < 2 || too_many(1LL * sides * rings) || !fits_float(inner) || !fits_float(outer)) return;
  std::vector<float> spsi, cpsi, sphi, cphi;
  circle(rings, false, spsi, cpsi);
  circle(-sides, false, sphi, cphi);
  const float ri = float(inner), ro = float(outer);
  Mesh m;
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < sides; ++i) {
      const float d = ro + cphi[size_t(i)] * ri;
      m.add({cpsi[size_t(j)] * d, spsi[size_t(j)] * d, sphi[size_t(i)] * ri},
            {cpsi[size_t(j)] * cphi[size_t(i)], spsi[size_t(j)] * cphi[size_t(i)], sphi[size_t(i)]});
    }
  if (wire) {
    for (int j = 0; j < rings; ++j) {
      std::vector<int> idx;
      for (int i = 0; i < sides; ++i) idx.push_back(j * sides + i);
      m.draw(GL_LINE_LOOP, idx);
    }
    for (int i = 0; i < sides; ++i) {
      std::vector<int> idx;
      for (int j = 0; j < rings; ++j) idx.push_back(j * sides + i);
      m.draw(GL_LINE_LOOP, idx);
    }
    return;
  }
  for (int i = 0; i < sides; ++i) {  // one strip per side, around every ring and back
    const int next = i == sides - 1 ? -i : 1;
    std::vector<int> idx;
    for (int j = 0; j <= rings; ++j) idx.push_back((j % rings) * sides + i), idx.push_back((j % rings) * sides + i + next);
    m.draw(GL_TRIANGLE_STRIP, idx);
  }
}

// A polyhedron: vertices, faces (each `per_face` vertex numbers, counter-clockwise
// from outside) and one normal a face. Solid: each face's triangles with the face's
// normal (a fan from its first vertex, freeglut's split; a pentagon 0-1-2, 0-2-4, 4-2-3).
// Wire: each face's outline.
struct Polyhedron {
  const float* v;
  const unsigned char* faces;
  const float* n;
  int face_count, per_face;

  void draw(float scale, bool wire) const {
    for (int f = 0; f < face_count; ++f) {
      const unsigned char* face = faces + f * per_face;
      const float* fn = n + 3 * f;
      const auto put = [&](int k) {
        const float* p = v + 3 * face[k];
        glNormal3f(fn[0], fn[1], fn[2]);
        glVertex3f(scale * p[0], scale * p[1], scale * p[2]);
      };
      if (wire) {
        glBegin(GL_LINE_LOOP);
        for (int k = 0; k < per_face; ++k) put(k);
        glEnd();
        continue;
      }
      static const int tri[] = {0, 1, 2}, quad[] = {0, 1, 2, 0, 2, 3}, pent[] = {0, 1, 2, 0, 2, 4, 4, 2, 3};
      const int* order = per_face == 3 ? tri : per_face == 4 ? quad : pent;
      const int count = per_face == 3 ? 3 : per_face == 4 ? 6 : 9;
      glBegin(GL_TRIANGLES);
      for (int k = 0; k < count; ++k) put(order[k]);
      glEnd();
    }
  }
};

// The solids' coordinates are the classic ones GLUT has always used (unit circumradius
// for the tetrahedron, octahedron and icosahedron; the dodecahedron's vertices at
// (±1, ±1, ±1), (0, ±φ, ±1/φ) and cyclic; the cube ±1/2 times its size).
const float kCubeV[] = {.5f, .5f, .5f, -.5f, .5f,  .5f,  -.5f, -.5f, .5f,  .5f,  -.5f, .5f,
                        .5f, -.5f, -.5f, .5f, .5f, -.5f, -.5f, .5f,  -.5f, -.5f, -.5f, -.5f};
const unsigned char kCubeF[] = {0, 1, 2, 3, 0, 3, 4, 5, 0, 5, 6, 1, 1, 6, 7, 2, 7, 4, 3, 2, 4, 7, 6, 5};
const float kCubeN[] = {0, 0, 1, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0, 0, 0, -1};

constexpr float kPhi = 1.61803398875f, kInvPhi = 0.61803398875f;
const float kDodecaV[] = {0,       kPhi,     kInvPhi, -1,       1,        1,  -kInvPhi, 0,        kPhi,
                          kInvPhi, 0,        kPhi,    1,        1,        1,  0,        kPhi,     -kInvPhi,
                          1,       1,        -1,      kInvPhi,  0,        -kPhi, -kInvPhi, 0,     -kPhi,
                          -1,      1,        -1,      0,        -kPhi,    kInvPhi, 1,       -1,       1,
                          -1,      -1,       1,       0,        -kPhi,    -kInvPhi, -1,      -1,       -1,
                          1,       -1,       -1,      kPhi,     -kInvPhi, 0,  kPhi,     kInvPhi,  0,
                          -kPhi,   kInvPhi,  0,       -kPhi,    -kInvPhi, 0};
const unsigned char kDodecaF[] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 3,  2,  12,
                                  13, 14, 8,  7,  15, 3,  11, 16, 17, 4,  2,  1,  18, 19, 12,
                                  7,  6,  17, 16, 15, 8,  14, 19, 18, 9,  17, 6,  5,  0,  4,
                                  16, 11, 10, 13, 15, 18, 1,  0,  5,  9,  19, 14, 13, 10, 12};
constexpr float kA = 0.525731112119f, kB = 0.850650808354f;
const float kDodecaN[] = {0,  kA, kB, 0,  kA, -kB, 0,  -kA, kB, 0,  -kA, -kB, kB, 0,   kA,  -kB, 0,  kA,
                          kB, 0,  -kA, -kB, 0, -kA, kA, kB,  0,  kA, -kB, 0,   -kA, kB, 0,   -kA, -kB, 0};

const float kIcosaV[] = {1,     0,      0,      0.447213595500f,  0.894427191000f,  0,     0.447213595500f,
                         0.276393202252f, 0.850650808354f, 0.447213595500f, -0.723606797748f, 0.525731112119f,
                         0.447213595500f, -0.723606797748f, -0.525731112119f, 0.447213595500f, 0.276393202252f,
                         -0.850650808354f, -0.447213595500f, -0.894427191000f, 0, -0.447213595500f,
                         -0.276393202252f, 0.850650808354f, -0.447213595500f, 0.723606797748f, 0.525731112119f,
                         -0.447213595500f, 0.723606797748f, -0.525731112119f, -0.447213595500f,
                         -0.276393202252f, -0.850650808354f, -1, 0, 0};
const unsigned char kIcosaF[] = {0, 1, 2, 0, 2, 3, 0, 3,  4, 0, 4,  5, 0,  5,  1, 1, 8,  2, 2,  7,
                                 3, 3, 6, 4, 4, 10, 5, 5, 9, 1, 1, 9, 8,  2,  8, 7, 3,  7, 6,  4,
                                 6, 10, 5, 10, 9, 11, 9, 10, 11, 8, 9, 11, 7, 8, 11, 6, 7, 11, 10, 6};

// Octahedron: the unit points on the axes. Tetrahedron: (1, 0, 0) and three points at
// x = -1/3 on the unit sphere.
const float kOctaV[] = {1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1};
const unsigned char kOctaF[] = {0, 1, 2, 0, 5, 1, 0, 2, 4, 0, 4, 5, 3, 2, 1, 3, 1, 5, 3, 4, 2, 3, 5, 4};
const float kTetraV[] = {1, 0, 0, -0.333333333333f, 0.942809041582f, 0, -0.333333333333f, -0.471404520791f,
                         0.816496580928f, -0.333333333333f, -0.471404520791f, -0.816496580928f};
const unsigned char kTetraF[] = {1, 3, 2, 0, 2, 3, 0, 3, 1, 0, 1, 2};

// A face's normal from its first three vertices (counter-clockwise from outside): unit,
// or the edges' cross product as it comes — freeglut's icosahedron normals are those,
// 0.957 long, which lighting without GL_NORMALIZE shows.
std::vector<float> normals_of(const float* v, const unsigned char* faces, int face_count, int per_face,
                              bool unit = true) {
  std::vector<float> n;
  for (int f = 0; f < face_count; ++f) {
    const float* a = v + 3 * faces[f * per_face];
    const float* b = v + 3 * faces[f * per_face + 1];
    const float* c = v + 3 * faces[f * per_face + 2];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2], z = u[0] * w[1] - u[1] * w[0];
    const double len = unit ? std::sqrt(x * x + y * y + z * z) : 1.0;
    n.push_back(float(x / len)), n.push_back(float(y / len)), n.push_back(float(z / len));
  }
  return n;
}

const Polyhedron& icosahedron() {
  static const std::vector<float> n = normals_of(kIcosaV, kIcosaF, 20, 3, false);
  static const Polyhedron p{kIcosaV, kIcosaF, n.data(), 20, 3};
  return p;
}
const Polyhedron& octahedron() {
  static const std::vector<float> n = normals_of(kOctaV, kOctaF, 8, 3);
  static const Polyhedron p{kOctaV, kOctaF, n.data(), 8, 3};
  return p;
}
const Polyhedron& tetrahedron() {
  static const std::vector<float> n = normals_of(kTetraV, kTetraF, 4, 3);
  static const Polyhedron p{kTetraV, kTetraF, n.data(), 4, 3};
  return p;
}
const Polyhedron kCube{kCubeV, kCubeF, kCubeN, 6, 4};
const Polyhedron kDodecahedron{kDodecaV, kDodecaF, kDodecaN, 12, 5};

}  // namespace

extern "C" {

void glutSolidSphere(double radius, GLint slices, GLint stacks) { sphere(radius, slices, stacks, false); }
void glutWireSphere(double radius, GLint slices, GLint stacks) { sphere(radius, slices, stacks, true); }
void glutSolidCone(double base, double height, GLint slices, GLint stacks) {
  cone(base, height, slices, stacks, false);
}
void glutWireCone(double base, double height, GLint slices, GLint stacks) { cone(base, height, slices, stacks, true); }
void glutSolidTorus(double inner, double outer, GLint sides, GLint rings) { torus(inner, outer, sides, rings, false); }
void glutWireTorus(double inner, double outer, GLint sides, GLint rings) { torus(inner, outer, sides, rings, true); }
void glutSolidCube(double size) {
  if (fits_float(size)) kCube.draw(float(size), false);
}
void glutWireCube(double size) {
  if (fits_float(size)) kCube.draw(float(size), true);
}
void glutSolidDodecahedron(void) { kDodecahedron.draw(1, false); }
void glutWireDodecahedron(void) { kDodecahedron.draw(1, true); }
void glutSolidIcosahedron(void) { icosahedron().draw(1, false); }
void glutWireIcosahedron(void) { icosahedron().draw(1, true); }
void glutSolidOctahedron(void) { octahedron().draw(1, false); }
void glutWireOctahedron(void) { octahedron().draw(1, true); }
void glutSolidTetrahedron(void) { tetrahedron().draw(1, false); }
void glutWireTetrahedron(void) { tetrahedron().draw(1, true); }

}  // extern "C"
