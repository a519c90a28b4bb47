// GLU quadrics: spheres, cylinders, disks and partial disks drawn through pGL's own
// glBegin/glNormal/glTexCoord/glVertex, so they meet the same pipeline as any program's
// geometry. Each shape is cut as SGI's GLU (Mesa's libGLU) cuts it — the same
// primitives, vertex order, normals (its "flat" normals included) and texture
// coordinates — so that a program's image matches the one it gives on Mesa.
// Errors are GLU's: GLU_INVALID_ENUM / GLU_INVALID_VALUE to the GLU_ERROR callback;
// GL's error state is untouched. A null quadric is ignored rather than dereferenced.
#include <GL/glu.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <vector>

struct GLUquadric {
  GLenum normals = GLU_SMOOTH;
  bool texture = false;
  GLenum orientation = GLU_OUTSIDE;
  GLenum style = GLU_FILL;
  void(GLAPIENTRY* error)(GLenum) = nullptr;
};

namespace {
constexpr double kPi = 3.14159265358979323846;
// GLU caps slices and stacks (a larger count is drawn at 239).
constexpr int kMaxDivisions = 239;

// GLU computes in float: a size or angle beyond float's range (or NaN) is refused, not
// converted (which C++ leaves undefined).
bool fits_float(double v) { return std::fabs(v) <= double(std::numeric_limits<float>::max()); }

void report(GLUquadric* q, GLenum error) {
  if (q->error) q->error(error);
}

// sin and cos of the angles `scale * (i + offset) / n`, i = 0..n, the last wrapping to
// the first when `wrap` (a closed ring: the seam's vertices are bit-identical).
struct Ring {
  std::vector<float> s, c;
  Ring(int n, double scale, double offset, bool wrap, double start = 0) : s(size_t(n) + 1), c(size_t(n) + 1) {
    for (int i = 0; i <= n; ++i) {
      const float angle = float(start + scale * (i + offset) / n);
      s[size_t(i)] = float(std::sin(angle)), c[size_t(i)] = float(std::cos(angle));
    }
    if (wrap) s[size_t(n)] = s[0], c[size_t(n)] = c[0];
  }
};

float tex_u(int i, int slices) { return 1 - float(i) / float(slices); }

// --- gluSphere ----------------------------------------------------------------------
struct Sphere {
  const GLUquadric& q;
  int slices, stacks;
  float radius;
  Ring around;       // vertex and smooth-normal directions around the axis
  Ring around_flat;  // GLU's flat normals: half a slice back
  std::vector<float> ring_r, ring_z;  // each stack boundary's radius and height
  std::vector<float> ns, nc;          // smooth normal's sin/cos from the pole, oriented
  std::vector<float> fs, fc;          // flat normal's, half a stack back, oriented

  Sphere(const GLUquadric& quad, double r, int sl, int st)
      : q(quad), slices(sl), stacks(st), radius(float(r)), around(sl, 2 * kPi, 0, true),
        around_flat(sl, 2 * kPi, -0.5, true) {
    const float sign = q.orientation == GLU_OUTSIDE ? 1.0f : -1.0f;
    for (int j = 0; j <= stacks; ++j) {
      const float a = float(kPi * j / stacks), af = float(kPi * (j - 0.5) / stacks);
      ring_r.push_back(float(r * std::sin(a)));
      ring_z.push_back(float(r * std::cos(a)));
      ns.push_back(sign * std::sin(a)), nc.push_back(sign * std::cos(a));
      fs.push_back(sign * std::sin(af)), fc.push_back(sign * std::cos(af));
    }
    ring_r.front() = ring_r.back() = 0;  // the poles are points
  }
  void vertex(int i, int j) const {
    const size_t k = size_t(i);
    glVertex3f(ring_r[size_t(j)] * around.s[k], ring_r[size_t(j)] * around.c[k], ring_z[size_t(j)]);
  }
  void smooth_normal(int i, int j) const {
    const size_t k = size_t(i);
    glNormal3f(around.s[k] * ns[size_t(j)], around.c[k] * ns[size_t(j)], nc[size_t(j)]);
  }
  void flat_normal(int i, int j) const {
    const size_t k = size_t(i);
    glNormal3f(around_flat.s[k] * fs[size_t(j)], around_flat.c[k] * fs[size_t(j)], fc[size_t(j)]);
  }
  // Untextured, GLU closes each pole with a fan (ring 1 or ring stacks-1 around it).
  void pole_fan(bool top) const {
    const int ring = top ? 1 : stacks - 1;
    if (q.normals == GLU_SMOOTH) glNormal3f(0, 0, top ? nc[0] : nc[size_t(stacks)]);
    glBegin(GL_TRIANGLE_FAN);
    glVertex3f(0, 0, top ? radius : -radius);
    // The fan turns so that its front faces the orientation's side.
    const bool descending = top == (q.orientation == GLU_OUTSIDE);
    for (int n = 0; n <= slices; ++n) {
      const int i = descending ? slices - n : n;
      if (q.normals == GLU_SMOOTH) smooth_normal(i, ring);
      if (q.normals == GLU_FLAT) {
        const int flat_ring = top ? 1 : stacks;
        if (!descending) flat_normal(i, flat_ring);
        else if (i != slices) flat_normal(i + 1, flat_ring);
      }
      vertex(i, ring);
    }
    glEnd();
  }
  void fill() const {
    int first = 0, last = stacks;
    if (!q.texture) {
      pole_fan(true);
      pole_fan(false);
      first = 1, last = stacks - 1;
    }
    const bool out = q.orientation == GLU_OUTSIDE;
    for (int j = first; j < last; ++j) {
      // Each strip pairs ring j+1 and ring j, the order the orientation asks.
      const int a = out ? j + 1 : j, b = out ? j : j + 1;
      glBegin(GL_QUAD_STRIP);
      for (int i = 0; i <= slices; ++i) {
        if (q.normals == GLU_SMOOTH) smooth_normal(i, a);
        if (q.texture) glTexCoord2f(tex_u(i, slices), 1 - float(a) / float(stacks));
        vertex(i, a);
        if (q.normals == GLU_SMOOTH) smooth_normal(i, b);
        if (q.normals == GLU_FLAT) flat_normal(i, j + 1);
        if (q.texture) glTexCoord2f(tex_u(i, slices), 1 - float(b) / float(stacks));
        vertex(i, b);
      }
      glEnd();
    }
  }
  void points() const {
    glBegin(GL_POINTS);
    for (int j = 0; j <= stacks; ++j)
      for (int i = 0; i < slices; ++i) {
        if (q.normals != GLU_NONE) smooth_normal(i, j);
        if (q.texture) glTexCoord2f(tex_u(i, slices), 1 - float(j) / float(stacks));
        vertex(i, j);
      }
    glEnd();
  }
  // GLU draws its silhouette as the line style: every ring and meridian.
  void lines() const {
    for (int j = 1; j < stacks; ++j) {
      glBegin(GL_LINE_STRIP);
      for (int i = 0; i <= slices; ++i) {
        const size_t k = size_t(i);
        if (q.normals == GLU_SMOOTH) smooth_normal(i, j);
        if (q.normals == GLU_FLAT)
          glNormal3f(around_flat.s[k] * ns[size_t(j)], around_flat.c[k] * ns[size_t(j)], nc[size_t(j)]);
        if (q.texture) glTexCoord2f(tex_u(i, slices), 1 - float(j) / float(stacks));
        vertex(i, j);
      }
      glEnd();
    }
    for (int i = 0; i < slices; ++i) {
      glBegin(GL_LINE_STRIP);
      for (int j = 0; j <= stacks; ++j) {
        if (q.normals == GLU_SMOOTH) smooth_normal(i, j);
        if (q.normals == GLU_FLAT) {
          const size_t k = size_t(i);
          glNormal3f(around.s[k] * fs[size_t(j)], around.c[k] * fs[size_t(j)], fc[size_t(j)]);
        }
        if (q.texture) glTexCoord2f(tex_u(i, slices), 1 - float(j) / float(stacks));
        vertex(i, j);
      }
      glEnd();
    }
  }
};

// --- gluCylinder --------------------------------------------------------------------
struct Cylinder {
  const GLUquadric& q;
  int slices, stacks;
  double base, delta, height;
  float z_normal;
  Ring around, around_flat;
  float xy;  // the normal's length in the xy plane, signed by the orientation

  Cylinder(const GLUquadric& quad, double b, double top, double h, int sl, int st, double length)
      : q(quad), slices(sl), stacks(st), base(b), delta(b - top), height(h), z_normal(float((b - top) / length)),
        around(sl, 2 * kPi, 0, true), around_flat(sl, 2 * kPi, -0.5, true),
        xy(float(h / length) * (quad.orientation == GLU_OUTSIDE ? 1.0f : -1.0f)) {}

  float z(int j) const { return float(j * height / stacks); }
  float r(int j) const { return float(base - delta * (float(j) / float(stacks))); }
  void vertex(int i, int j) const {
    glVertex3f(r(j) * around.s[size_t(i)], r(j) * around.c[size_t(i)], z(j));
  }
  void tex(int i, int j) const {
    if (q.texture) glTexCoord2f(tex_u(i, slices), float(j) / float(stacks));
  }
  // The points' normal: GLU gives the smooth one for both normal kinds.
  void point_normal(int i) const {
    if (q.normals != GLU_NONE) glNormal3f(xy * around.s[size_t(i)], xy * around.c[size_t(i)], z_normal);
  }
  // The shared normal rule of fill and ring lines: flat or smooth per the quadric.
  void side_normal(int i) const {
    if (q.normals == GLU_NONE) return;
    const Ring& ring = q.normals == GLU_FLAT ? around_flat : around;
    glNormal3f(xy * ring.s[size_t(i)], xy * ring.c[size_t(i)], z_normal);
  }
  void fill() const {
    const bool out = q.orientation == GLU_OUTSIDE;
    for (int j = 0; j < stacks; ++j) {
      const int a = out ? j : j + 1, b = out ? j + 1 : j;
      glBegin(GL_QUAD_STRIP);
      for (int i = 0; i <= slices; ++i) {
        side_normal(i);
        tex(i, a), vertex(i, a);
        tex(i, b), vertex(i, b);
      }
      glEnd();
    }
  }
  void points() const {
    glBegin(GL_POINTS);
    for (int i = 0; i < slices; ++i) {
      point_normal(i);
      for (int j = 0; j <= stacks; ++j) tex(i, j), vertex(i, j);
    }
    glEnd();
  }
  void ring(int j) const {
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i <= slices; ++i) side_normal(i), tex(i, j), vertex(i, j);
    glEnd();
  }
  // Line: every ring, then the silhouette's (the two end rings and the meridians).
  void lines(bool all_rings) const {
    if (all_rings)
      for (int j = 1; j < stacks; ++j) ring(j);
    ring(0);
    ring(stacks);
    for (int i = 0; i < slices; ++i) {
      if (q.normals != GLU_NONE) glNormal3f(xy * around.s[size_t(i)], xy * around.c[size_t(i)], 0);
      glBegin(GL_LINE_STRIP);
      for (int j = 0; j <= stacks; ++j) tex(i, j), vertex(i, j);
      glEnd();
    }
  }
};

// --- gluPartialDisk -----------------------------------------------------------------
struct Disk {
  const GLUquadric& q;
  int slices, loops;
  double inner, outer, delta;
  bool full;
  Ring around;

  Disk(const GLUquadric& quad, double in, double out, int sl, int lo, double start, double sweep)
      : q(quad), slices(sl), loops(lo), inner(in), outer(out), delta(out - in), full(sweep == 360.0),
        around(sl, kPi * sweep / 180.0, 0, sweep == 360.0, start / 180.0 * kPi) {}

  float r(int j) const { return float(outer - delta * (float(j) / float(loops))); }
  void point(int i, float radius) const {
    const size_t k = size_t(i);
    if (q.texture) {
      const float t = float(radius / outer / 2);
      glTexCoord2f(t * around.s[k] + 0.5f, t * around.c[k] + 0.5f);
    }
    glVertex3f(radius * around.s[k], radius * around.c[k], 0);
  }
  void ring(float radius) const {
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i <= slices; ++i) point(i, radius);
    glEnd();
  }
  void spoke(int i) const {
    glBegin(GL_LINE_STRIP);
    for (int j = 0; j <= loops; ++j) point(i, r(j));
    glEnd();
  }
  int spokes() const { return full ? slices : slices + 1; }
  void fill() const {
    const bool out = q.orientation == GLU_OUTSIDE;
    int strips = loops;
    if (inner == 0.0) {  // the centre loop is a fan
      strips = loops - 1;
      glBegin(GL_TRIANGLE_FAN);
      if (q.texture) glTexCoord2f(0.5f, 0.5f);
      glVertex3f(0, 0, 0);
      const float radius = r(loops - 1);
      for (int n = 0; n <= slices; ++n) point(out ? slices - n : n, radius);
      glEnd();
    }
    for (int j = 0; j < strips; ++j) {
      const float a = out ? r(j) : r(j + 1), b = out ? r(j + 1) : r(j);
      glBegin(GL_QUAD_STRIP);
      for (int i = 0; i <= slices; ++i) point(i, a), point(i, b);
      glEnd();
    }
  }
  void points() const {
    glBegin(GL_POINTS);
    for (int i = 0; i < spokes(); ++i)
      for (int j = 0; j <= loops; ++j) point(i, r(j));
    glEnd();
  }
  void lines() const {
    if (inner == outer) {  // a circle: its texture coordinates span the whole disk
      glBegin(GL_LINE_STRIP);
      for (int i = 0; i <= slices; ++i) {
        const size_t k = size_t(i);
        if (q.texture) glTexCoord2f(around.s[k] / 2 + 0.5f, around.c[k] / 2 + 0.5f);
        glVertex3f(float(inner) * around.s[k], float(inner) * around.c[k], 0);
      }
      glEnd();
      return;
    }
    for (int j = 0; j <= loops; ++j) ring(r(j));
    for (int i = 0; i < spokes(); ++i) spoke(i);
  }
  void silhouette() const {
    if (!full) spoke(0), spoke(slices);
    ring(r(0));
    if (inner != outer) ring(r(loops));
  }
};

}  // namespace

extern "C" {

GLUquadric* gluNewQuadric(void) { return new (std::nothrow) GLUquadric; }

void gluDeleteQuadric(GLUquadric* q) { delete q; }

void gluQuadricCallback(GLUquadric* q, GLenum which, _GLUfuncptr callback) {
  if (!q) return;
  if (which != GLU_ERROR) return report(q, GLU_INVALID_ENUM);
  q->error = reinterpret_cast<void(GLAPIENTRY*)(GLenum)>(callback);
}

void gluQuadricNormals(GLUquadric* q, GLenum normals) {
  if (!q) return;
  if (normals != GLU_SMOOTH && normals != GLU_FLAT && normals != GLU_NONE) return report(q, GLU_INVALID_ENUM);
  q->normals = normals;
}

void gluQuadricTexture(GLUquadric* q, GLboolean texture) {
  if (q) q->texture = texture != GL_FALSE;
}

void gluQuadricOrientation(GLUquadric* q, GLenum orientation) {
  if (!q) return;
  if (orientation != GLU_OUTSIDE && orientation != GLU_INSIDE) return report(q, GLU_INVALID_ENUM);
  q->orientation = orientation;
}

void gluQuadricDrawStyle(GLUquadric* q, GLenum style) {
  if (!q) return;
  if (style != GLU_POINT && style != GLU_LINE && style != GLU_FILL && style != GLU_SILHOUETTE)
    return report(q, GLU_INVALID_ENUM);
  q->style = style;
}

void gluSphere(GLUquadric* q, GLdouble radius, GLint slices, GLint stacks) {
  if (!q) return;
  slices = std::min(slices, kMaxDivisions), stacks = std::min(stacks, kMaxDivisions);
  if (slices < 2 || stacks < 1 || !(radius >= 0.0) || !fits_float(radius))
    return report(q, GLU_INVALID_VALUE);
  const Sphere s(*q, radius, slices, stacks);
  if (q->style == GLU_FILL) s.fill();
  else if (q->style == GLU_POINT) s.points();
  else s.lines();
}

void gluCylinder(GLUquadric* q, GLdouble base, GLdouble top, GLdouble height, GLint slices, GLint stacks) {
  if (!q) return;
  slices = std::min(slices, kMaxDivisions);
  if (slices < 2 || stacks < 1 || !(base >= 0.0) || !(top >= 0.0) || !(height >= 0.0) ||
      !fits_float(base) || !fits_float(top) || !fits_float(height))
    return report(q, GLU_INVALID_VALUE);
  // A cylinder of no size has no normal (GLU: an error).
  const double length = std::hypot(base - top, height);
  if (length == 0.0) return report(q, GLU_INVALID_VALUE);
  const Cylinder c(*q, base, top, height, slices, stacks, length);
  if (q->style == GLU_FILL) c.fill();
  else if (q->style == GLU_POINT) c.points();
  else c.lines(q->style == GLU_LINE);
}

void gluPartialDisk(GLUquadric* q, GLdouble inner, GLdouble outer, GLint slices, GLint loops, GLdouble start,
                    GLdouble sweep) {
  if (!q) return;
  slices = std::min(slices, kMaxDivisions);
  if (slices < 2 || loops < 1 || !(outer > 0.0) || !(inner >= 0.0) || inner > outer ||
      !fits_float(outer) || !fits_float(start) || std::isnan(sweep))
    return report(q, GLU_INVALID_VALUE);
  // GLU's sweep: at most a turn (below -360 counts as a full turn), negative turns back.
  if (sweep < -360.0 || sweep > 360.0) sweep = 360.0;
  if (sweep < 0) start += sweep, sweep = -sweep;
  if (q->normals != GLU_NONE) glNormal3f(0, 0, q->orientation == GLU_OUTSIDE ? 1.0f : -1.0f);
  const Disk d(*q, inner, outer, slices, loops, start, sweep);
  switch (q->style) {
    case GLU_FILL: d.fill(); break;
    case GLU_POINT: d.points(); break;
    case GLU_LINE: d.lines(); break;
    default: d.silhouette(); break;
  }
}

void gluDisk(GLUquadric* q, GLdouble inner, GLdouble outer, GLint slices, GLint loops) {
  gluPartialDisk(q, inner, outer, slices, loops, 0.0, 360.0);
}

}  // extern "C"
