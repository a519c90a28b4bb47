/* One-dimensional evaluators: a cubic and a quintic Bezier curve (GL_MAP1_VERTEX_3,
 * GL_MAP1_VERTEX_4 with weights) through glEvalCoord1f and glEvalCoord1d, with a colour
 * map (GL_MAP1_COLOR_4) and a texture map (GL_MAP1_TEXTURE_COORD_2) on a textured
 * strip of points; glMapGrid1 with glEvalMesh1 (GL_LINE, GL_POINT) and glEvalPoint1; glMap1d
 * with a stride; all compiled into a display list (piglit's dlist-fdo31590 case);
 * glEvalCoord1 leaving the current colour alone. Values: glGetMap (COEFF, ORDER,
 * DOMAIN), GL_MAP1_GRID_*, GL_MAX_EVAL_ORDER, glIsEnabled, the errors. */
#include "harness.h"

static const GLfloat cubic[4][3] = {{-0.9f, -0.9f, 0}, {-0.6f, 0.9f, 0}, {0.2f, -0.9f, 0}, {0.9f, 0.8f, 0}};

int main(int argc, char** argv) {
  GLfloat quintic[6][4];
  GLdouble strided[4 * 5];
  GLfloat colors[3][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0.2f, 0.3f, 1, 1}};
  GLfloat tex[2][2] = {{0.04f, 0}, {3.04f, 1}}; /* off the texel boundaries (at s = k/8) */
  GLfloat fv[32];
  GLint iv[4];
  GLuint list;
  int i;
  conf_init(argc, argv, 128, 128);
  glClearColor(0.05f, 0.05f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glGetIntegerv(GL_MAX_EVAL_ORDER, iv);
  conf_value("max_order", iv[0]);

  /* The cubic, coloured by a colour map, through glEvalCoord1f in a line strip. */
  glViewport(0, 64, 64, 64);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &cubic[0][0]);
  glMap1f(GL_MAP1_COLOR_4, 0, 1, 4, 3, &colors[0][0]);
  glEnable(GL_MAP1_VERTEX_3);
  glEnable(GL_MAP1_COLOR_4);
  conf_value("enabled_vertex3", glIsEnabled(GL_MAP1_VERTEX_3));
  glColor3f(0.5f, 0.5f, 0.5f);
  glPointSize(4); /* points, not a line strip: the curve's short lines rasterize a few pixels apart */
  glBegin(GL_POINTS);
  for (i = 0; i <= 40; ++i) glEvalCoord1f((GLfloat)i / 40);
  glEnd();
  glPointSize(1);
  glGetFloatv(GL_CURRENT_COLOR, fv);
  conf_value("current_red_kept", fv[0]);

  /* The quintic with weights (GL_MAP1_VERTEX_4) over a domain [2, 5], by glEvalCoord1d
   * points, and as glEvalMesh1 lines in another viewport. */
  for (i = 0; i < 6; ++i) {
    const float w = i == 2 || i == 3 ? 2.0f : 1.0f;
    quintic[i][0] = (-0.9f + 0.36f * (float)i) * w;
    quintic[i][1] = (i % 2 ? 0.8f : -0.7f) * w;
    quintic[i][2] = 0;
    quintic[i][3] = w;
  }
  glDisable(GL_MAP1_COLOR_4);
  glMap1f(GL_MAP1_VERTEX_4, 2, 5, 4, 6, &quintic[0][0]);
  glEnable(GL_MAP1_VERTEX_4);
  glViewport(64, 64, 64, 64);
  glColor3f(1, 1, 0);
  glPointSize(2);
  glBegin(GL_POINTS);
  for (i = 0; i <= 12; ++i) glEvalCoord1d(2.0 + 3.0 * i / 12);
  glEnd();
  glPointSize(1);
  glMapGrid1f(30, 2, 5);
  glColor3f(0, 1, 1);
  glEvalMesh1(GL_LINE, 0, 30);
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, iv);
  conf_value("grid_segments", iv[0]);
  glGetFloatv(GL_MAP1_GRID_DOMAIN, fv);
  conf_value("grid_u1", fv[0]);
  conf_value("grid_u2", fv[1]);
  glDisable(GL_MAP1_VERTEX_4);

  /* A textured strip: positions from a strided glMap1d, texture coordinates from a
   * map, points of a grid by glEvalPoint1 and glEvalMesh1(GL_POINT). */
  for (i = 0; i < 4; ++i) {
    strided[5 * i] = -0.8 + 0.5 * i, strided[5 * i + 1] = i % 2 ? 0.6 : -0.6, strided[5 * i + 2] = 0;
    strided[5 * i + 3] = 99, strided[5 * i + 4] = 99; /* skipped by the stride */
  }
  glMap1d(GL_MAP1_VERTEX_3, 0, 1, 5, 4, strided);
  glMap1f(GL_MAP1_TEXTURE_COORD_2, 0, 1, 2, 2, &tex[0][0]);
  glEnable(GL_MAP1_TEXTURE_COORD_2);
  {
    static const GLubyte stripes[8 * 4] = {255, 0, 0, 255, 255, 255, 255, 255, 0, 0, 255, 255, 0, 0, 0, 255,
                                           0, 255, 0, 255, 255, 255, 0, 255, 255, 0, 255, 255, 0, 255, 255, 255};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, stripes);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
  }
  glViewport(0, 0, 64, 64);
  glColor3f(1, 1, 1);
  glMapGrid1d(24, 0, 1);
  glPointSize(4);
  glEvalMesh1(GL_POINT, 0, 24);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_MAP1_TEXTURE_COORD_2);
  glColor3f(1, 0.5f, 0);
  glBegin(GL_POINTS);
  glEvalPoint1(0);
  glEvalPoint1(12);
  glEvalPoint1(24);
  glEnd();
  glPointSize(1);
  glEvalMesh1(GL_POINT, 3, 9);

  /* In a display list (as piglit's dlist-fdo31590): the cubic again, yellow. (The
   * colour is set before glBegin: Mesa 22 drops a glColor compiled between glBegin and
   * glEvalCoord1, drawing the curve white; pGL draws it yellow, as GL says.) */
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &cubic[0][0]);
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glColor3f(1, 1, 0);
  glBegin(GL_LINE_STRIP);
  for (i = 0; i <= 30; ++i) glEvalCoord1f((GLfloat)i / 30);
  glEnd();
  glEndList();
  conf_value("list_error", glGetError());
  glViewport(64, 0, 64, 64);
  glColor3f(1, 1, 1);
  glCallList(list);
  conf_value("call_error", glGetError());
  glViewport(0, 0, 128, 128);
  conf_frame("curves");

  /* glGetMap. */
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, iv);
  conf_value("order", iv[0]);
  glGetMapfv(GL_MAP1_VERTEX_4, GL_DOMAIN, fv);
  conf_value("domain_u1", fv[0]);
  conf_value("domain_u2", fv[1]);
  glGetMapfv(GL_MAP1_VERTEX_3, GL_COEFF, fv);
  conf_value("coeff_4", fv[4]);
  conf_value("coeff_9", fv[9]);
  glGetMapiv(GL_MAP1_NORMAL, GL_ORDER, iv);
  conf_value("normal_order", iv[0]);
  glGetMapfv(GL_MAP1_NORMAL, GL_COEFF, fv);
  conf_value("normal_initial_z", fv[2]);

  /* Errors. */
  glMap1f(GL_TEXTURE_2D, 0, 1, 3, 4, &cubic[0][0]);
  conf_value("map_bad_target", glGetError());
  glMap1f(GL_MAP1_VERTEX_3, 1, 1, 3, 4, &cubic[0][0]);
  conf_value("map_empty_domain", glGetError());
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 2, 4, &cubic[0][0]);
  conf_value("map_small_stride", glGetError());
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 0, &cubic[0][0]);
  conf_value("map_order_0", glGetError());
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 31, &cubic[0][0]);
  conf_value("map_order_31", glGetError());
  glMapGrid1f(0, 0, 1);
  conf_value("grid_zero", glGetError());
  glEvalMesh1(GL_FILL, 0, 3);
  conf_value("mesh_fill", glGetError());
  glGetMapfv(GL_MAP1_VERTEX_3, GL_RGBA, fv);
  conf_value("get_bad_query", glGetError());
  glBegin(GL_POINTS);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &cubic[0][0]);
  glEnd();
  conf_value("map_in_begin", glGetError());
  glDeleteLists(list, 1);
  return conf_end();
}
