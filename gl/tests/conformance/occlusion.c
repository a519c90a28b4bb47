/* GL 1.5's occlusion queries (GL_SAMPLES_PASSED): the fragments that pass the depth
 * and stencil tests, counted per query and compared with Mesa's counts exactly.
 *
 * Boxes in front of, behind and around a first box (each result read at once, and all
 * read after the last query); a query with colour and depth writes off; the stencil
 * test, the alpha test, the scissor test and polygon stipple removing fragments; points
 * and lines on exact pixels; a query over no draws; a query begun again on the same
 * name; a query whose draws are in a display list. Values: glGetQueryiv
 * (GL_QUERY_COUNTER_BITS, GL_CURRENT_QUERY), glIsQuery, GL_QUERY_RESULT_AVAILABLE as
 * both entry points return it, the errors. The frame is compared too. */
#define GL_GLEXT_PROTOTYPES 1
#include "harness.h"

static void box(float x, float y, float z, float w, float h) {
  glBegin(GL_QUADS);
  glVertex3f(x, y, z);
  glVertex3f(x + w, y, z);
  glVertex3f(x + w, y + h, z);
  glVertex3f(x, y + h, z);
  glEnd();
}

static GLuint q[8];

static void result(const char* name, GLuint id) {
  GLuint u = 0;
  GLint i = 0;
  glGetQueryObjectuiv(id, GL_QUERY_RESULT, &u);
  glGetQueryObjectiv(id, GL_QUERY_RESULT, &i);
  conf_value(name, u);
  if ((GLint)u != i) conf_value("iv_differs", i);
}

/* Boxes relative to a first 50 x 50 box at depth 0 (in glOrtho's -z: nearer is larger). */
static void boxes(float x, int all_at_once) {
  static const float t[5][5] = {{25, 25, 0.2f, 20, 20},
                                {45, 45, -0.2f, 20, 20},
                                {10, 10, -0.3f, 70, 70},
                                {20, 20, -0.1f, 50, 50},
                                {50, 25, 0.2f, 20, 27}};
  static const char* const names[2][5] = {{"front", "behind", "around", "same", "front_tall"},
                                          {"all_front", "all_behind", "all_around", "all_same", "all_front_tall"}};
  int i;
  glColor3ub(200, 30, 30);
  box(x + 20, 20, 0, 50, 50);
  for (i = 0; i < 5; ++i) {
    glBeginQuery(GL_SAMPLES_PASSED, q[i]);
    glColor3ub((GLubyte)(40 * i), (GLubyte)(255 - 30 * i), 120);
    box(x + t[i][0], t[i][1], t[i][2], t[i][3], t[i][4]);
    glEndQuery(GL_SAMPLES_PASSED);
    if (!all_at_once) result(names[0][i], q[i]);
  }
  if (all_at_once)
    for (i = 0; i < 5; ++i) result(names[1][i], q[i]);
}

int main(int argc, char** argv) {
  GLint iv = -1;
  GLuint u;
  GLuint list;
  int i;
  conf_stencil_bits = 8;
  conf_init(argc, argv, 200, 120);
  conf_ortho();
  glClearColor(0.0f, 0.2f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, &iv);
  conf_value("counter_bits", iv);
  glGenQueries(8, q);
  conf_value("is_query_generated", glIsQuery(q[0]));
  conf_value("names_differ", q[0] != q[1] && q[0] != 0);

  boxes(0, 0);
  conf_value("is_query_used", glIsQuery(q[0]));
  boxes(90, 1);

  /* Colour and depth writes off: the fragments still count; nothing changes. */
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glBeginQuery(GL_SAMPLES_PASSED, q[5]);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &iv);
  conf_value("current_is_q5", iv == (GLint)q[5]);
  box(5, 80, 0.5f, 30, 30);
  box(5, 80, -0.9f, 30, 30); /* behind the first: none */
  glEndQuery(GL_SAMPLES_PASSED);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &iv);
  conf_value("current_after", iv);
  result("masked", q[5]);

  /* The stencil test: a 10 x 10 square of 1s; only it passes the second draw. */
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glColor3ub(255, 255, 0);
  box(150, 10, 0.6f, 10, 10);
  glStencilFunc(GL_EQUAL, 1, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glBeginQuery(GL_SAMPLES_PASSED, q[6]);
  glColor3ub(0, 255, 255);
  box(145, 5, 0.7f, 30, 30);
  glEndQuery(GL_SAMPLES_PASSED);
  glDisable(GL_STENCIL_TEST);
  result("stencil", q[6]);

  /* The alpha test (a smooth alpha ramp), the scissor and the polygon stipple. */
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.5f);
  glBeginQuery(GL_SAMPLES_PASSED, q[7]);
  glBegin(GL_QUADS);
  glColor4f(1, 1, 1, 0);
  glVertex3f(110, 80, 0.8f);
  glColor4f(1, 1, 1, 1);
  glVertex3f(150, 80, 0.8f);
  glVertex3f(150, 110, 0.8f);
  glColor4f(1, 1, 1, 0);
  glVertex3f(110, 110, 0.8f);
  glEnd();
  glEndQuery(GL_SAMPLES_PASSED);
  glDisable(GL_ALPHA_TEST);
  result("alpha", q[7]);
  glEnable(GL_SCISSOR_TEST);
  glScissor(160, 60, 7, 9);
  glBeginQuery(GL_SAMPLES_PASSED, q[7]); /* the same name again: counts from zero */
  glColor3ub(90, 90, 255);
  box(155, 55, 0.8f, 40, 40);
  glEndQuery(GL_SAMPLES_PASSED);
  glDisable(GL_SCISSOR_TEST);
  result("scissor", q[7]);
  {
    GLubyte pattern[128];
    for (i = 0; i < 128; ++i) pattern[i] = (GLubyte)(i % 8 < 4 ? 0xf0 : 0x3c);
    glPolygonStipple(pattern);
    glEnable(GL_POLYGON_STIPPLE);
    glBeginQuery(GL_SAMPLES_PASSED, q[0]);
    glColor3ub(255, 128, 0);
    box(170, 90, 0.8f, 24, 24);
    glEndQuery(GL_SAMPLES_PASSED);
    glDisable(GL_POLYGON_STIPPLE);
    result("stipple", q[0]);
  }

  /* Points and lines on exact pixels (depth test off). */
  glDisable(GL_DEPTH_TEST);
  glBeginQuery(GL_SAMPLES_PASSED, q[1]);
  glPointSize(3);
  glBegin(GL_POINTS);
  glVertex2f(100.5f, 5.5f);
  glVertex2f(110.5f, 5.5f);
  glEnd();
  glPointSize(1);
  glBegin(GL_LINES);
  glVertex2f(100.5f, 12.5f);
  glVertex2f(130.5f, 12.5f);
  glEnd();
  glEndQuery(GL_SAMPLES_PASSED);
  result("points_lines", q[1]);

  /* No draws between begin and end; draws from a display list. */
  glBeginQuery(GL_SAMPLES_PASSED, q[2]);
  glEndQuery(GL_SAMPLES_PASSED);
  result("empty", q[2]);
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  box(60, 90, 0, 12, 13);
  glEndList();
  glBeginQuery(GL_SAMPLES_PASSED, q[3]);
  glCallList(list);
  glEndQuery(GL_SAMPLES_PASSED);
  u = 7;
  glGetQueryObjectuiv(q[3], GL_QUERY_RESULT_AVAILABLE, &u);
  glFinish();
  glGetQueryObjectuiv(q[3], GL_QUERY_RESULT_AVAILABLE, &u);
  conf_value("available_after_finish", u);
  result("list", q[3]);
  glEnable(GL_DEPTH_TEST);
  conf_frame("queried");

  /* Errors. */
  glBeginQuery(GL_TEXTURE_2D, q[0]);
  conf_value("begin_bad_target", glGetError());
  glBeginQuery(GL_SAMPLES_PASSED, 0);
  conf_value("begin_zero", glGetError());
  glBeginQuery(GL_SAMPLES_PASSED, q[0]);
  glBeginQuery(GL_SAMPLES_PASSED, q[1]);
  conf_value("begin_nested", glGetError());
  glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &u);
  conf_value("result_of_active", glGetError());
  glDeleteQueries(1, &q[0]);
  conf_value("delete_active", glGetError());
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &iv);
  conf_value("current_after_delete", iv);
  glEndQuery(GL_SAMPLES_PASSED);
  conf_value("end_none_active", glGetError());
  glEndQuery(GL_TEXTURE_2D);
  conf_value("end_bad_target", glGetError());
  glGetQueryObjectuiv(q[1], GL_RGBA, &u);
  conf_value("object_bad_name", glGetError());
  glGetQueryObjectuiv(9999, GL_QUERY_RESULT, &u);
  conf_value("object_unknown", glGetError());
  glGetQueryiv(GL_SAMPLES_PASSED, GL_RGBA, &iv);
  conf_value("query_bad_name", glGetError());
  glGenQueries(-1, q);
  conf_value("gen_negative", glGetError());
  glBegin(GL_TRIANGLES);
  glBeginQuery(GL_SAMPLES_PASSED, q[1]);
  glEnd();
  conf_value("begin_in_begin", glGetError());
  conf_value("is_query_deleted", glIsQuery(q[0]));
  glDeleteQueries(8, q);
  conf_value("is_query_after", glIsQuery(q[1]));
  conf_value("final_error", glGetError());
  glDeleteLists(list, 1);
  return conf_end();
}
