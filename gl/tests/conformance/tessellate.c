/* GLU's tessellator on pGL: concave and self-intersecting polygons, a polygon with two
 * holes, all five winding rules, GLU_TESS_BOUNDARY_ONLY, a combine callback that mixes
 * colours at the intersections, an edge-flag callback with GL_LINE polygon mode (the
 * edges inside the polygon are not drawn), the *_DATA callbacks, gluTessNormal,
 * gluBeginPolygon / gluNextContour, the error callback, gluGetTessProperty. Against
 * Velocity the tessellator is Debian's libGLU calling pGL, against Mesa the same libGLU
 * calling OSMesa: the frames compare pGL's drawing of what it emits, the values the
 * primitives and vertices counted. */
#include <math.h>

#include "harness.h"

#ifndef CALLBACK
#define CALLBACK
#endif

static int begins, vertices, combines, edge_changes, errors, last_error;
static GLdouble combined[64][7];

static void CALLBACK on_begin(GLenum mode) {
  ++begins;
  glBegin(mode);
}
static void CALLBACK on_vertex(void* data) {
  const GLdouble* v = (const GLdouble*)data;
  ++vertices;
  glColor3dv(v + 3);
  glVertex3dv(v);
}
static void CALLBACK on_end(void) { glEnd(); }
static void CALLBACK on_edge(GLboolean flag) {
  ++edge_changes;
  glEdgeFlag(flag);
}
static void CALLBACK on_error(GLenum e) { ++errors, last_error = (int)e; }
/* A new vertex where edges cross: its position, and its colour weighted from the four. */
static void CALLBACK on_combine(GLdouble coords[3], void* data[4], GLfloat weight[4], void** out) {
  GLdouble* v = combined[combines++ % 64];
  int i, k;
  for (i = 0; i < 3; ++i) v[i] = coords[i];
  for (k = 3; k < 6; ++k) {
    v[k] = 0;
    for (i = 0; i < 4; ++i)
      if (data[i]) v[k] += weight[i] * ((GLdouble*)data[i])[k];
  }
  *out = v;
}
static void* polygon_data;
static void CALLBACK on_begin_data(GLenum mode, void* data) {
  polygon_data = data;
  on_begin(mode);
}
static void CALLBACK on_vertex_data(void* v, void* data) {
  (void)data;
  on_vertex(v);
}

/* A contour of n vertices (x, y, z, r, g, b). */
static void contour(GLUtesselator* t, GLdouble (*v)[6], int n) {
  int i;
  gluTessBeginContour(t);
  for (i = 0; i < n; ++i) gluTessVertex(t, v[i], v[i]);
  gluTessEndContour(t);
}

static GLdouble outer[6][6] = {{-0.9, -0.9, 0, 1, 0, 0},  {0.9, -0.8, 0, 0, 1, 0}, {0.7, 0.1, 0, 0, 0, 1},
                               {0.95, 0.9, 0, 1, 1, 0},   {-0.2, 0.3, 0, 0, 1, 1}, {-0.85, 0.8, 0, 1, 0, 1}};
static GLdouble hole1[4][6] = {{-0.6, -0.6, 0, 1, 1, 1}, {-0.6, -0.2, 0, 1, 1, 1}, {-0.2, -0.2, 0, 1, 1, 1},
                               {-0.2, -0.6, 0, 1, 1, 1}};
static GLdouble hole2[3][6] = {{0.2, -0.6, 0, 0.5, 0.5, 0.5}, {0.3, -0.2, 0, 0.5, 0.5, 0.5},
                               {0.6, -0.55, 0, 0.5, 0.5, 0.5}};
/* A star drawn in one stroke: self-intersecting, winding numbers 1 and 2. */
static GLdouble star[5][6] = {{0, 0.9, 0, 1, 0, 0},   {0.55, -0.75, 0, 0, 1, 0}, {-0.85, 0.3, 0, 0, 0, 1},
                              {0.85, 0.3, 0, 1, 1, 0}, {-0.55, -0.75, 0, 0, 1, 1}};
/* Two overlapping squares, the second clockwise: winding numbers 1, 0 and -1. */
static GLdouble square_a[4][6] = {{-0.8, -0.8, 0, 1, 0.5, 0}, {0.3, -0.8, 0, 1, 0.5, 0}, {0.3, 0.3, 0, 1, 0.5, 0},
                                  {-0.8, 0.3, 0, 1, 0.5, 0}};
static GLdouble square_b[4][6] = {{-0.3, -0.3, 0, 0, 0.5, 1}, {-0.3, 0.8, 0, 0, 0.5, 1}, {0.8, 0.8, 0, 0, 0.5, 1},
                                  {0.8, -0.3, 0, 0, 0.5, 1}};

static void tile(int i, int size) { glViewport((i % 4) * size, (i / 4) * size, size, size); }

static void count(const char* name) {
  char n[64];
  snprintf(n, sizeof n, "%s_begins", name);
  conf_value(n, begins);
  snprintf(n, sizeof n, "%s_vertices", name);
  conf_value(n, vertices);
  snprintf(n, sizeof n, "%s_combines", name);
  conf_value(n, combines);
  begins = vertices = combines = edge_changes = 0;
}

int main(int argc, char** argv) {
  static const GLenum rules[5] = {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_POSITIVE,
                                  GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO};
  const int size = 48;
  GLUtesselator* t;
  GLdouble d;
  int r, tile_at = 0;
  char name[64];
  conf_init(argc, argv, 4 * size, 4 * size);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  t = gluNewTess();
  gluTessCallback(t, GLU_TESS_BEGIN, (_GLUfuncptr)on_begin);
  gluTessCallback(t, GLU_TESS_VERTEX, (_GLUfuncptr)on_vertex);
  gluTessCallback(t, GLU_TESS_END, (_GLUfuncptr)on_end);
  gluTessCallback(t, GLU_TESS_COMBINE, (_GLUfuncptr)on_combine);
  gluTessCallback(t, GLU_TESS_ERROR, (_GLUfuncptr)on_error);
  gluTessNormal(t, 0, 0, 1);

  /* A concave polygon with two holes. */
  tile(tile_at++, size);
  gluTessBeginPolygon(t, NULL);
  contour(t, outer, 6);
  contour(t, hole1, 4);
  contour(t, hole2, 3);
  gluTessEndPolygon(t);
  count("holes");

  /* The star and the two squares under each winding rule. */
  for (r = 0; r < 5; ++r) {
    gluTessProperty(t, GLU_TESS_WINDING_RULE, rules[r]);
    gluGetTessProperty(t, GLU_TESS_WINDING_RULE, &d);
    snprintf(name, sizeof name, "rule%d", r);
    conf_value(name, d);
    tile(tile_at++, size);
    gluTessBeginPolygon(t, NULL);
    contour(t, star, 5);
    gluTessEndPolygon(t);
    snprintf(name, sizeof name, "star%d", r);
    count(name);
    tile(tile_at++, size);
    gluTessBeginPolygon(t, NULL);
    contour(t, square_a, 4);
    contour(t, square_b, 4);
    gluTessEndPolygon(t);
    snprintf(name, sizeof name, "squares%d", r);
    count(name);
  }
  gluTessProperty(t, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_ODD);

  /* Edge flags: with an edge-flag callback GLU sends independent triangles; in GL_LINE
   * mode only the polygon's own edges are drawn. */
  gluTessCallback(t, GLU_TESS_EDGE_FLAG, (_GLUfuncptr)on_edge);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  tile(tile_at++, size);
  gluTessBeginPolygon(t, NULL);
  contour(t, outer, 6);
  contour(t, hole1, 4);
  gluTessEndPolygon(t);
  conf_value("edge_changes", edge_changes);
  count("edges");
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  gluTessCallback(t, GLU_TESS_EDGE_FLAG, NULL);

  /* Boundary only: the contours as line loops. */
  gluTessProperty(t, GLU_TESS_BOUNDARY_ONLY, GL_TRUE);
  tile(tile_at++, size);
  gluTessBeginPolygon(t, NULL);
  contour(t, star, 5);
  gluTessEndPolygon(t);
  count("boundary");
  gluTessProperty(t, GLU_TESS_BOUNDARY_ONLY, GL_FALSE);

  /* The *_DATA callbacks with the polygon's data. */
  gluTessCallback(t, GLU_TESS_BEGIN, NULL);
  gluTessCallback(t, GLU_TESS_VERTEX, NULL);
  gluTessCallback(t, GLU_TESS_BEGIN_DATA, (_GLUfuncptr)on_begin_data);
  gluTessCallback(t, GLU_TESS_VERTEX_DATA, (_GLUfuncptr)on_vertex_data);
  tile(tile_at++, size);
  gluTessBeginPolygon(t, &tile_at);
  contour(t, square_a, 4);
  gluTessEndPolygon(t);
  conf_value("polygon_data", polygon_data == &tile_at);
  count("data");

  /* GLU 1.1's interface: gluBeginPolygon, gluNextContour, gluEndPolygon. */
  gluTessCallback(t, GLU_TESS_BEGIN_DATA, NULL);
  gluTessCallback(t, GLU_TESS_VERTEX_DATA, NULL);
  gluTessCallback(t, GLU_BEGIN, (_GLUfuncptr)on_begin);
  gluTessCallback(t, GLU_VERTEX, (_GLUfuncptr)on_vertex);
  tile(tile_at++, size);
  gluBeginPolygon(t);
  {
    int i;
    for (i = 0; i < 6; ++i) gluTessVertex(t, outer[i], outer[i]);
    gluNextContour(t, GLU_INTERIOR);
    for (i = 0; i < 3; ++i) gluTessVertex(t, hole2[i], hole2[i]);
  }
  gluEndPolygon(t);
  count("glu11");

  /* Errors: a vertex outside a contour, a crossing without a combine callback. */
  gluTessBeginPolygon(t, NULL);
  gluTessVertex(t, outer[0], outer[0]);
  gluTessEndPolygon(t);
  conf_value("error_missing_contour", last_error);
  gluTessCallback(t, GLU_TESS_COMBINE, NULL);
  tile(tile_at++, size);
  gluTessBeginPolygon(t, NULL);
  contour(t, star, 5);
  gluTessEndPolygon(t);
  conf_value("error_need_combine", last_error);
  conf_value("errors", errors);
  count("no_combine");
  gluDeleteTess(t);
  conf_value("gl_error", glGetError());
  conf_frame("tessellated");
  return conf_end();
}
