/* GLU NURBS (Debian's libGLU, drawing through GL's evaluators): the OpenGL Programming
 * Guide's "surface.c" (a lit 4x4 NURBS surface, GLU_FILL, then GLU_OUTLINE_POLYGON),
 * its "trim.c" (the surface trimmed by a piecewise-linear outer loop and an inner loop
 * of a NURBS curve and a line), a rational curve (a circle of 9 weighted points,
 * gluNurbsCurve on GL_MAP1_VERTEX_4) and a non-uniform cubic; GLU_SAMPLING_METHOD
 * GLU_DOMAIN_DISTANCE with a fixed step; the properties read back with
 * gluGetNurbsProperty; GLU_NURBS_TESSELLATOR mode (GLU 1.3's callbacks: no GL drawing)
 * counting the primitives and vertices it gives; errors to GLU_NURBS_ERROR. */
#include "harness.h"

static GLfloat ctlpoints[4][4][3];
static int nurbs_errors, last_error;
static int tess_begins, tess_vertices, tess_normals;

static void GLAPIENTRY on_error(GLenum error) {
  ++nurbs_errors;
  last_error = (int)error;
}
static void GLAPIENTRY on_begin(GLenum type) {
  (void)type;
  ++tess_begins;
}
static void GLAPIENTRY on_vertex(GLfloat* v) {
  (void)v;
  ++tess_vertices;
}
static void GLAPIENTRY on_normal(GLfloat* n) {
  (void)n;
  ++tess_normals;
}
static void GLAPIENTRY on_end(void) {}

static void init_surface(void) {
  int u, v;
  for (u = 0; u < 4; ++u)
    for (v = 0; v < 4; ++v) {
      ctlpoints[u][v][0] = 2.0f * ((GLfloat)u - 1.5f);
      ctlpoints[u][v][1] = 2.0f * ((GLfloat)v - 1.5f);
      ctlpoints[u][v][2] = (u == 1 || u == 2) && (v == 1 || v == 2) ? 3.0f : -3.0f;
    }
}

static void view(GLdouble x) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45, 1, 3, 8);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef((GLfloat)x, 0, -5);
  glRotatef(330, 1, 0, 0);
  glRotatef(20, 0, 1, 0);
  glScalef(0.5f, 0.5f, 0.5f);
}

static void lights(void) {
  static const GLfloat diffuse[4] = {0.7f, 0.7f, 0.7f, 1};
  static const GLfloat specular[4] = {1, 1, 1, 1};
  static const GLfloat position[4] = {1, 1, 1, 0};
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 100);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_NORMALIZE);
}

static void surface(GLUnurbs* nurb) {
  static GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  gluBeginSurface(nurb);
  gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 3, 3, &ctlpoints[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
}

int main(int argc, char** argv) {
  static GLfloat edge[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  static GLfloat curve_pt[4][2] = {{0.25f, 0.5f}, {0.25f, 0.75f}, {0.75f, 0.75f}, {0.75f, 0.5f}};
  static GLfloat curve_knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  static GLfloat pwl_pt[3][2] = {{0.75f, 0.5f}, {0.5f, 0.25f}, {0.25f, 0.5f}};
  /* A circle: 9 points of a quadratic rational curve, weights 1 and 1/sqrt(2). */
  static const GLfloat circle_knots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
  static const GLfloat cubic_knots[10] = {0, 0, 0, 0, 0.3f, 1.5f, 2, 2, 2, 2};
  static const GLfloat cubic_pts[6][3] = {{-0.9f, -0.6f, 0}, {-0.5f, 0.8f, 0}, {-0.1f, -0.9f, 0},
                                          {0.3f, 0.9f, 0},   {0.6f, -0.2f, 0}, {0.9f, 0.7f, 0}};
  GLfloat circle[9][4];
  GLfloat value;
  GLUnurbs* nurb;
  int i;
  conf_init(argc, argv, 160, 160);
  init_surface();
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  lights();

  nurb = gluNewNurbsRenderer();
  gluNurbsCallback(nurb, GLU_NURBS_ERROR, (_GLUfuncptr)on_error);
  gluNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, 25.0f);
  gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_FILL);

  /* surface.c: the surface, filled, in the left half; as outlined polygons in the right. */
  glViewport(0, 40, 80, 80);
  view(0);
  surface(nurb);
  gluEndSurface(nurb);
  glViewport(80, 80, 80, 80);
  gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_OUTLINE_POLYGON);
  glDisable(GL_LIGHTING);
  glColor3f(0.3f, 1, 0.5f);
  view(0);
  surface(nurb);
  gluEndSurface(nurb);
  gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_FILL);
  glEnable(GL_LIGHTING);

  /* trim.c: an outer counter-clockwise square, an inner clockwise loop of a curve and
   * a line; the sampling by parametric distance. */
  glViewport(80, 0, 80, 80);
  view(0);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(nurb, GLU_U_STEP, 12);
  gluNurbsProperty(nurb, GLU_V_STEP, 9);
  surface(nurb);
  gluBeginTrim(nurb);
  gluPwlCurve(nurb, 5, &edge[0][0], 2, GLU_MAP1_TRIM_2);
  gluEndTrim(nurb);
  gluBeginTrim(nurb);
  gluNurbsCurve(nurb, 8, curve_knots, 2, &curve_pt[0][0], 4, GLU_MAP1_TRIM_2);
  gluPwlCurve(nurb, 3, &pwl_pt[0][0], 2, GLU_MAP1_TRIM_2);
  gluEndTrim(nurb);
  gluEndSurface(nurb);
  conf_frame("surfaces");

  /* Curves: the rational circle and the non-uniform cubic, on the identity view. */
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glClear(GL_COLOR_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  for (i = 0; i < 9; ++i) {
    static const float xs[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, ys[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    const float w = i % 2 ? 0.70710678f : 1.0f;
    circle[i][0] = (0.45f * xs[i] - 0.3f) * w;
    circle[i][1] = (0.7f * ys[i] + 0.1f) * w;
    circle[i][2] = 0;
    circle[i][3] = w;
  }
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_PATH_LENGTH);
  gluNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, 10.0f);
  glViewport(0, 0, 160, 160);
  glColor3f(1, 0.8f, 0.2f);
  gluBeginCurve(nurb);
  gluNurbsCurve(nurb, 12, (GLfloat*)circle_knots, 4, &circle[0][0], 3, GL_MAP1_VERTEX_4);
  gluEndCurve(nurb);
  glColor3f(0.3f, 0.8f, 1);
  gluBeginCurve(nurb);
  gluNurbsCurve(nurb, 10, (GLfloat*)cubic_knots, 3, (GLfloat*)&cubic_pts[0][0], 4, GL_MAP1_VERTEX_3);
  gluEndCurve(nurb);
  conf_frame("curves");

  /* Properties. */
  gluGetNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, &value);
  conf_value("sampling_tolerance", value);
  gluGetNurbsProperty(nurb, GLU_DISPLAY_MODE, &value);
  conf_value("display_mode", value);
  gluGetNurbsProperty(nurb, GLU_U_STEP, &value);
  conf_value("u_step", value);
  gluGetNurbsProperty(nurb, GLU_CULLING, &value);
  conf_value("culling", value);
  conf_value("gl_error", glGetError());

  /* Errors: a knot count that does not match the order, a surface not begun. */
  gluBeginCurve(nurb);
  gluNurbsCurve(nurb, 5, (GLfloat*)cubic_knots, 3, (GLfloat*)&cubic_pts[0][0], 4, GL_MAP1_VERTEX_3);
  gluEndCurve(nurb);
  conf_value("bad_knots_errors", nurbs_errors);
  conf_value("bad_knots_error", last_error);
  gluEndSurface(nurb);
  conf_value("end_errors", nurbs_errors);
  conf_value("gl_error_after", glGetError());
  gluDeleteNurbsRenderer(nurb);

  /* GLU 1.3's tessellator mode: the same surface as primitives to callbacks, counted;
   * GL draws nothing (the frame stays clear). */
  glClear(GL_COLOR_BUFFER_BIT);
  nurb = gluNewNurbsRenderer();
  gluNurbsProperty(nurb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
  gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  gluNurbsProperty(nurb, GLU_U_STEP, 6);
  gluNurbsProperty(nurb, GLU_V_STEP, 5);
  gluNurbsCallback(nurb, GLU_NURBS_BEGIN, (_GLUfuncptr)on_begin);
  gluNurbsCallback(nurb, GLU_NURBS_VERTEX, (_GLUfuncptr)on_vertex);
  gluNurbsCallback(nurb, GLU_NURBS_NORMAL, (_GLUfuncptr)on_normal);
  gluNurbsCallback(nurb, GLU_NURBS_END, (_GLUfuncptr)on_end);
  surface(nurb);
  gluEndSurface(nurb);
  conf_value("tess_begins", tess_begins);
  conf_value("tess_vertices", tess_vertices);
  conf_value("tess_normals", tess_normals);
  gluDeleteNurbsRenderer(nurb);
  conf_frame("tessellator_mode");
  return conf_end();
}
