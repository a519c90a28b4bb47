/* All ten glBegin modes, smooth and flat shading (GL's provoking vertex for each mode),
 * point sizes and line widths. */
#include <math.h>

#include "harness.h"

static void color_of(int i) {
  static const float c[7][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}};
  glColor3fv(c[i % 7]);
}

/* Mode `mode` in a cell centred on (cx, cy), radius r. */
static void draw_mode(GLenum mode, float cx, float cy, float r) {
  int i;
  glBegin(mode);
  switch (mode) {
    case GL_QUADS:
      for (i = 0; i < 8; ++i) {
        static const float q[8][2] = {{-1, -1}, {-0.1f, -1}, {-0.1f, 0.9f}, {-1, 0.7f}, {0.1f, -0.8f}, {1, -1}, {0.9f, 1}, {0.1f, 0.6f}};
        color_of(i);
        glVertex2f(cx + r * q[i][0], cy + r * q[i][1]);
      }
      break;
    case GL_QUAD_STRIP:
    case GL_TRIANGLE_STRIP:
      for (i = 0; i < 8; ++i) {
        color_of(i);
        glVertex2f(cx + r * (-1 + 2.0f * (i / 2) / 3.0f), cy + r * (i % 2 ? 0.8f : -0.8f) + 0.05f * r * (i % 3));
      }
      break;
    default:
      /* A ring of vertices (fans and polygons start at the centre-ish first vertex). */
      if (mode == GL_TRIANGLE_FAN) {
        glColor3f(0.5f, 0.5f, 0.5f);
        glVertex2f(cx, cy);
      }
      for (i = 0; i < (mode == GL_TRIANGLES ? 9 : 7); ++i) {
        const float a = 6.2831853f * i / (mode == GL_TRIANGLES ? 9 : 7) + 0.3f;
        const float rr = mode == GL_TRIANGLES ? r * (i % 3 == 0 ? 0.3f : 1.0f) : r;
        color_of(i);
        glVertex2f(cx + rr * cosf(a), cy + rr * sinf(a));
      }
      break;
  }
  glEnd();
}

int main(int argc, char** argv) {
  static const GLenum modes[10] = {GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLES,
                                   GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};
  int shade;
  conf_init(argc, argv, 200, 100);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, 200, 0, 100);
  glMatrixMode(GL_MODELVIEW);
  for (shade = 0; shade < 2; ++shade) {
    int m;
    glShadeModel(shade ? GL_FLAT : GL_SMOOTH);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glPointSize(3);
    glLineWidth(1);
    for (m = 0; m < 10; ++m) draw_mode(modes[m], 20.0f + 40.0f * (m % 5), 75.0f - 50.0f * (m / 5), 16);
    conf_frame(shade ? "flat" : "smooth");
  }
  /* Sizes: points of 1, 2, 5 pixels, lines of 1, 3, 5 pixels (even line widths: see
   * docs/gl.md, Velocity centres the extra pixel row on the other side). */
  glShadeModel(GL_SMOOTH);
  glClear(GL_COLOR_BUFFER_BIT);
  {
    int k;
    for (k = 0; k < 3; ++k) {
      static const float ps[3] = {1, 2, 5}, lw[3] = {1, 3, 5};
      glPointSize(ps[k]);
      glBegin(GL_POINTS);
      color_of(k);
      glVertex2f(20.3f + 30 * k, 80.2f);
      glVertex2f(25.2f + 30 * k, 70.3f);
      glEnd();
      glLineWidth(lw[k]);
      glBegin(GL_LINES);
      color_of(k + 3);
      glVertex2f(10.2f + 60 * k, 10.3f);
      glVertex2f(60.2f + 60 * k, 40.3f);
      glVertex2f(10.3f + 60 * k, 50.2f);
      glVertex2f(15.3f + 60 * k, 60.2f);
      glEnd();
    }
  }
  conf_frame("sizes");

  /* The quad split, seen in colours that are not affine across a quad: one inside the
   * view volume (split along v0 - v2), one with corners outside it in the same frame
   * (Mesa's clipper splits it along v1 - v3), and glRect, a quad. */
  glPointSize(1);
  glLineWidth(1);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glViewport(0, 0, 100, 100);
  glBegin(GL_QUADS);
  glColor3f(1, 0, 0), glVertex2f(-0.9f, -0.9f);
  glColor3f(0, 1, 0), glVertex2f(0.9f, -0.9f);
  glColor3f(0, 0, 1), glVertex2f(0.9f, 0.9f);
  glColor3f(1, 1, 1), glVertex2f(-0.9f, 0.9f);
  glEnd();
  glViewport(100, 0, 100, 100);
  glBegin(GL_QUADS);
  glColor3f(1, 0, 0), glVertex2f(-1.4f, -1.3f);
  glColor3f(0, 1, 0), glVertex2f(1.2f, -1.5f);
  glColor3f(0, 0, 1), glVertex2f(1.3f, 1.2f);
  glColor3f(1, 1, 1), glVertex2f(-1.5f, 1.4f);
  glEnd();
  conf_frame("quad_split");
  glViewport(0, 0, 200, 100);
  glClear(GL_COLOR_BUFFER_BIT);
  glShadeModel(GL_FLAT);
  glColor3f(0, 1, 1);
  glRectf(-0.5f, -0.5f, 0.5f, 0.7f);
  conf_frame("rect");

  /* Edge flags: polygon mode LINE and POINT draw only the edges (and vertices) whose
   * first vertex is flagged, for triangles, quads and polygons, from glEdgeFlag and
   * from an edge-flag array. (Not strips and fans: GL ignores their flags, Mesa does
   * not: docs/gl.md.) */
  {
    static const GLfloat tri[8] = {-0.9f, -0.9f, -0.1f, -0.9f, -0.5f, -0.1f, -0.9f, -0.1f};
    static const GLboolean flags[4] = {GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE};
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(1, 1, 0);
    glBegin(GL_QUADS);
    glEdgeFlag(GL_TRUE), glVertex2f(0.1f, 0.1f);
    glEdgeFlag(GL_FALSE), glVertex2f(0.9f, 0.1f);
    glEdgeFlag(GL_TRUE), glVertex2f(0.9f, 0.9f);
    glEdgeFlag(GL_FALSE), glVertex2f(0.1f, 0.9f);
    glEnd();
    glEdgeFlag(GL_TRUE);
    glVertexPointer(2, GL_FLOAT, 0, tri);
    glEdgeFlagPointer(0, flags);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glColor3f(0, 1, 1);
    glDrawArrays(GL_POLYGON, 0, 4);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(3);
    glTranslatef(1.003f, 0.013f, 0); /* the points off pixel boundaries */
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    conf_frame("edge_flags");
  }
  return conf_end();
}
