/* Two-dimensional evaluators: a bicubic patch (GL_MAP2_VERTEX_3) lit with GL_AUTO_NORMAL
 * through glEvalMesh2(GL_FILL) under a perspective, and a rational one (GL_MAP2_VERTEX_4,
 * weights off 1) lit the same way; a coloured, textured patch (GL_MAP2_COLOR_4,
 * GL_MAP2_TEXTURE_COORD_2) over a domain [2, 5] x [-1, 1] by glEvalMesh2 on part of a
 * grid; the mesh's GL_LINE and GL_POINT modes, glEvalPoint2, glEvalCoord2f/d/fv/dv;
 * each other map: GL_MAP2_NORMAL lit without GL_AUTO_NORMAL, texture coordinates from
 * GL_MAP2_TEXTURE_COORD_1, _3 and _4 (q dividing), GL_MAP2_INDEX (accepted, no effect);
 * a glMap2d with strides; glMap2, glMapGrid2 and glEvalMesh2 in a display list;
 * glPushAttrib(GL_EVAL_BIT) and GL_ENABLE_BIT. Values: glGetMap for 2-D maps (COEFF,
 * ORDER, DOMAIN), GL_MAP2_GRID_*, glIsEnabled, the current values kept, the errors. */
#include "harness.h"

/* A bicubic patch over [-1, 1]^2, heights asymmetric in u and v. */
static GLfloat patch[4][4][3];
static const GLfloat heights[4][4] = {{0, 0.4f, -0.2f, 0.1f}, {0.3f, 1.2f, 0.6f, -0.3f},
                                      {-0.4f, 0.2f, 1.0f, 0.2f}, {0.1f, -0.5f, 0.3f, 0.6f}};

static void make_patch(void) {
  int i, j;
  for (i = 0; i < 4; ++i)
    for (j = 0; j < 4; ++j) {
      patch[i][j][0] = -1 + 2.0f * (float)i / 3 + (j == 3 ? 0.2f : 0);
      patch[i][j][1] = -1 + 2.0f * (float)j / 3;
      patch[i][j][2] = heights[i][j];
    }
}

static void light_on(void) {
  static const GLfloat position[4] = {0.4f, 0.7f, 1, 0};
  static const GLfloat diffuse[4] = {0.9f, 0.8f, 0.6f, 1};
  static const GLfloat front[4] = {0.3f, 0.7f, 1, 1};
  static const GLfloat back[4] = {1, 0.4f, 0.2f, 1};
  glPushMatrix();
  glLoadIdentity(); /* the light in eye space, towards the viewer */
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glPopMatrix();
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, front);
  glMaterialfv(GL_BACK, GL_DIFFUSE, back);
  /* One-sided: GL's mesh winds its quads clockwise in (u, v), so that a face whose
   * du x dv points at the viewer is a back face (two-sided lighting would turn it away). */
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHTING);
}

static void perspective(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.6, 0.6, -0.6, 0.6, 1.5, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -3.6f);
  glRotatef(-55, 1, 0, 0);
  glRotatef(25, 0, 0, 1);
}

static void flat_view(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

int main(int argc, char** argv) {
  GLfloat rational[3][3][4];
  GLdouble strided[3 * 2 * 5];
  GLfloat colors[2][2][4] = {{{1, 0, 0, 1}, {0, 1, 0, 1}}, {{0, 0, 1, 1}, {1, 1, 0.2f, 1}}};
  GLfloat tex[2][2][2] = {{{0.02f, 0.03f}, {0.02f, 2.03f}}, {{3.02f, 0.03f}, {3.02f, 2.03f}}};
  GLfloat normals[2][2][3] = {{{0, 0, 1}, {0.7f, 0, 0.7f}}, {{0, 0.7f, 0.7f}, {-0.6f, -0.3f, 0.7f}}};
  GLfloat tex1[2][2][1] = {{{0.02f}, {0.52f}}, {{2.02f}, {1.02f}}};
  GLfloat tex4[2][2][4] = {{{0, 0, 0, 1}, {0, 1, 0, 2}}, {{2, 0, 0, 1}, {1, 1, 0, 0.5f}}};
  GLfloat flat_patch[2][2][3] = {{{-0.9f, -0.9f, 0}, {-0.9f, 0.9f, 0}}, {{0.9f, -0.9f, 0}, {0.8f, 0.7f, 0}}};
  GLfloat fv[64];
  GLdouble dv[4];
  GLint iv[4];
  GLuint list;
  int i, j;
  static const GLubyte checks[4 * 4 * 4] = {
      255, 0,   0,   255, 255, 255, 255, 255, 0,   0,   255, 255, 0,   0,   0,   255,
      0,   255, 0,   255, 255, 255, 0,   255, 255, 0,   255, 255, 0,   255, 255, 255,
      128, 64,  0,   255, 0,   128, 64,  255, 64,  0,   128, 255, 200, 200, 200, 255,
      255, 128, 128, 255, 128, 255, 128, 255, 128, 128, 255, 255, 30,  30,  30,  255};
  conf_init(argc, argv, 128, 128);
  make_patch();
  glClearColor(0.05f, 0.05f, 0.1f, 1);
  glEnable(GL_DEPTH_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  /* The lit bicubic patch, normals by GL_AUTO_NORMAL; u along
   * the first index (the stride of 12), so that du x dv faces the light. */
  glViewport(0, 64, 64, 64);
  perspective();
  light_on();
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &patch[0][0][0]);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  conf_value("enabled_auto_normal", glIsEnabled(GL_AUTO_NORMAL));
  conf_value("enabled_vertex3", glIsEnabled(GL_MAP2_VERTEX_3));
  glNormal3f(0.1f, 0.2f, 0.3f);
  glMapGrid2f(10, 0, 1, 7, 0, 1);
  glEvalMesh2(GL_FILL, 0, 10, 0, 7);
  glGetFloatv(GL_CURRENT_NORMAL, fv);
  conf_value("current_normal_kept_y", fv[1]);

  /* The rational patch: a 3x3 GL_MAP2_VERTEX_4 with the middle row's weights 2 and 0.5. */
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j) {
      const float w = j == 1 ? (i == 1 ? 0.5f : 2.0f) : 1.0f;
      rational[i][j][0] = (-1 + (float)i) * w;
      rational[i][j][1] = (-1 + (float)j) * w;
      rational[i][j][2] = (i == 1 && j == 1 ? 1.2f : (float)(i - j) * 0.3f) * w;
      rational[i][j][3] = w;
    }
  glViewport(64, 64, 64, 64);
  glMap2f(GL_MAP2_VERTEX_4, -1, 1, 12, 3, 0, 2, 4, 3, &rational[0][0][0]);
  glDisable(GL_MAP2_VERTEX_3);
  glEnable(GL_MAP2_VERTEX_4);
  glMapGrid2f(12, -1, 1, 9, 0, 2);
  glEvalMesh2(GL_FILL, 0, 12, 0, 9);
  glDisable(GL_MAP2_VERTEX_4);
  glEnable(GL_MAP2_VERTEX_3);

  /* GL_MAP2_NORMAL on a flat patch, lit, without GL_AUTO_NORMAL. */
  glDisable(GL_AUTO_NORMAL);
  glViewport(0, 0, 64, 64);
  flat_view();
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, &flat_patch[0][0][0]);
  glMap2f(GL_MAP2_NORMAL, 0, 1, 3, 2, 0, 1, 6, 2, &normals[0][0][0]);
  glEnable(GL_MAP2_NORMAL);
  glMapGrid2f(6, 0, 1, 6, 0, 1);
  glEvalMesh2(GL_FILL, 0, 6, 0, 6);
  glDisable(GL_MAP2_NORMAL);
  glDisable(GL_LIGHTING);

  /* A rational patch by GL_LINE over part of a grid, points on top (glEvalPoint2 and
   * each glEvalCoord2 form). */
  glViewport(64, 0, 64, 64);
  perspective();
  glDisable(GL_MAP2_VERTEX_3);
  glEnable(GL_MAP2_VERTEX_4);
  glColor3f(0.2f, 1, 0.4f);
  glMapGrid2f(8, -1, 1, 8, 0, 2);
  glEvalMesh2(GL_LINE, 1, 7, 0, 6);
  glColor3f(1, 0.3f, 0.3f);
  glPointSize(3);
  glEvalMesh2(GL_POINT, 0, 8, 7, 8);
  glBegin(GL_POINTS);
  glEvalPoint2(0, 0);
  glEvalPoint2(8, 0);
  glEvalCoord2f(0, 1);
  glEvalCoord2d(-0.5, 1.5);
  fv[0] = 0.5f, fv[1] = 0.5f;
  glEvalCoord2fv(fv);
  dv[0] = 0.25, dv[1] = 1.75;
  glEvalCoord2dv(dv);
  glEnd();
  glPointSize(1);
  glDisable(GL_MAP2_VERTEX_4);
  glViewport(0, 0, 128, 128);
  conf_frame("lit");

  /* A coloured, textured patch over [2, 5] x [-1, 1], part of the grid; GL_MAP2_INDEX
   * given and enabled does nothing in RGBA mode. */
  glDisable(GL_DEPTH_TEST);
  glClear(GL_COLOR_BUFFER_BIT);
  flat_view();
  glViewport(0, 64, 64, 64);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, checks);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);
  glMap2f(GL_MAP2_VERTEX_3, 2, 5, 3, 2, -1, 1, 6, 2, &flat_patch[0][0][0]);
  glMap2f(GL_MAP2_COLOR_4, 2, 5, 4, 2, -1, 1, 8, 2, &colors[0][0][0]);
  glMap2f(GL_MAP2_TEXTURE_COORD_2, 2, 5, 2, 2, -1, 1, 4, 2, &tex[0][0][0]);
  fv[0] = 3;
  glMap2f(GL_MAP2_INDEX, 2, 5, 1, 1, -1, 1, 1, 1, fv);
  glEnable(GL_MAP2_INDEX);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_MAP2_COLOR_4);
  glEnable(GL_MAP2_TEXTURE_COORD_2);
  glColor3f(0.5f, 0.5f, 0.5f);
  glMapGrid2d(12, 2, 5, 8, -1, 1);
  glEvalMesh2(GL_FILL, 2, 10, 1, 8);
  glGetFloatv(GL_CURRENT_COLOR, fv);
  conf_value("current_red_kept", fv[0]);
  glDisable(GL_MAP2_COLOR_4);
  glDisable(GL_MAP2_INDEX);

  /* Texture coordinates from GL_MAP2_TEXTURE_COORD_1 (the most coordinates win: 2 is
   * disabled first), _3 and _4 (q dividing s and t). */
  glColor3f(1, 1, 1);
  glDisable(GL_MAP2_TEXTURE_COORD_2);
  glViewport(64, 64, 64, 64);
  glMap2f(GL_MAP2_TEXTURE_COORD_1, 2, 5, 1, 2, -1, 1, 2, 2, &tex1[0][0][0]);
  glEnable(GL_MAP2_TEXTURE_COORD_1);
  glMapGrid2f(6, 2, 5, 6, -1, 1);
  glEvalMesh2(GL_FILL, 0, 6, 0, 6);
  glViewport(0, 0, 64, 64);
  glMap2f(GL_MAP2_TEXTURE_COORD_4, 2, 5, 4, 2, -1, 1, 8, 2, &tex4[0][0][0]);
  glEnable(GL_MAP2_TEXTURE_COORD_4);
  glEvalMesh2(GL_FILL, 0, 6, 0, 6);
  glDisable(GL_MAP2_TEXTURE_COORD_4);
  glDisable(GL_MAP2_TEXTURE_COORD_1);
  /* _3 from a strided glMap2d (r ignored by a 2-D texture). */
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 2; ++j) {
      GLdouble* p = &strided[(i * 2 + j) * 5];
      p[0] = 0.02 + 1.5 * i, p[1] = 0.03 + 2.0 * j + 0.3 * i, p[2] = 7, p[3] = 99, p[4] = 99;
    }
  glMap2d(GL_MAP2_TEXTURE_COORD_3, 2, 5, 10, 3, -1, 1, 5, 2, strided);
  glEnable(GL_MAP2_TEXTURE_COORD_3);
  glViewport(64, 0, 64, 64);
  glEvalMesh2(GL_FILL, 0, 6, 0, 6);
  glDisable(GL_MAP2_TEXTURE_COORD_3);
  glDisable(GL_TEXTURE_2D);
  glViewport(0, 0, 128, 128);
  conf_frame("attributes");

  /* glGetMap of the 2-D maps and the grid. */
  glGetMapiv(GL_MAP2_TEXTURE_COORD_3, GL_ORDER, iv);
  conf_value("order_u", iv[0]);
  conf_value("order_v", iv[1]);
  glGetMapfv(GL_MAP2_TEXTURE_COORD_3, GL_COEFF, fv);
  conf_value("coeff_3", fv[3]);
  conf_value("coeff_13", fv[13]);
  conf_value("coeff_17", fv[17]);
  glGetMapdv(GL_MAP2_VERTEX_4, GL_DOMAIN, dv);
  conf_value("domain_u1", dv[0]);
  conf_value("domain_u2", dv[1]);
  conf_value("domain_v1", dv[2]);
  conf_value("domain_v2", dv[3]);
  glGetMapfv(GL_MAP2_VERTEX_4, GL_COEFF, fv);
  conf_value("rational_coeff_19", fv[19]);
  glGetMapiv(GL_MAP2_TEXTURE_COORD_2, GL_ORDER, iv);
  conf_value("initial_order_u", iv[0]);
  glGetMapfv(GL_MAP2_COLOR_4, GL_DOMAIN, fv);
  conf_value("color_domain_v2", fv[3]);
  glGetMapfv(GL_MAP2_NORMAL, GL_COEFF, fv);
  conf_value("normal_coeff_11", fv[11]);
  glGetIntegerv(GL_MAP2_GRID_SEGMENTS, iv);
  conf_value("grid_un", iv[0]);
  conf_value("grid_vn", iv[1]);
  glGetFloatv(GL_MAP2_GRID_DOMAIN, fv);
  conf_value("grid_u1", fv[0]);
  conf_value("grid_u2", fv[1]);
  conf_value("grid_v1", fv[2]);
  conf_value("grid_v2", fv[3]);

  /* glPushAttrib: GL_EVAL_BIT restores the grid, the enables and GL_AUTO_NORMAL, not
   * the maps; GL_ENABLE_BIT the enables alone. */
  glEnable(GL_AUTO_NORMAL);
  glPushAttrib(GL_EVAL_BIT);
  glMapGrid2f(3, 0, 1, 4, 0, 1);
  glMapGrid1f(5, 0, 2);
  glDisable(GL_AUTO_NORMAL);
  glDisable(GL_MAP2_VERTEX_3);
  glEnable(GL_MAP2_COLOR_4);
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, &colors[0][0][0]);
  glPopAttrib();
  glGetIntegerv(GL_MAP2_GRID_SEGMENTS, iv);
  conf_value("popped_grid_un", iv[0]);
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, iv);
  conf_value("popped_grid1_n", iv[0]);
  conf_value("popped_auto_normal", glIsEnabled(GL_AUTO_NORMAL));
  conf_value("popped_vertex3", glIsEnabled(GL_MAP2_VERTEX_3));
  conf_value("popped_color4", glIsEnabled(GL_MAP2_COLOR_4));
  glGetMapfv(GL_MAP2_COLOR_4, GL_DOMAIN, fv);
  conf_value("map_kept_domain_u1", fv[0]);
  glPushAttrib(GL_ENABLE_BIT);
  glMapGrid2f(5, 0, 1, 5, 0, 1);
  glDisable(GL_AUTO_NORMAL);
  glDisable(GL_MAP2_VERTEX_3);
  glPopAttrib();
  glGetIntegerv(GL_MAP2_GRID_SEGMENTS, iv);
  conf_value("enable_popped_grid_un", iv[0]);
  conf_value("enable_popped_auto_normal", glIsEnabled(GL_AUTO_NORMAL));
  conf_value("enable_popped_vertex3", glIsEnabled(GL_MAP2_VERTEX_3));

  /* A display list holding glMap2f (its points copied at compile time), glMapGrid2f and
   * the mesh: the patch lit with GL_AUTO_NORMAL, then lines over it. */
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &patch[0][0][0]);
  glMapGrid2f(9, 0, 1, 9, 0, 1);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  glEvalMesh2(GL_FILL, 0, 9, 0, 9);
  glEndList();
  conf_value("list_error", glGetError());
  patch[1][1][2] = -3; /* changed after compiling: the list keeps its copy */
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, &flat_patch[0][0][0]);
  perspective();
  light_on();
  glCallList(list);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glColor3f(1, 1, 0);
  glMapGrid2f(4, 0, 1, 4, 0, 1);
  glEvalMesh2(GL_LINE, 0, 4, 0, 4);
  conf_value("call_error", glGetError());
  conf_frame("list");

  /* Errors. */
  glMap2f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, &flat_patch[0][0][0]);
  conf_value("map_bad_target", glGetError());
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 1, 1, 6, 2, &flat_patch[0][0][0]);
  conf_value("map_empty_v_domain", glGetError());
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 2, 2, &flat_patch[0][0][0]);
  conf_value("map_small_vstride", glGetError());
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 0, 0, 1, 6, 2, &flat_patch[0][0][0]);
  conf_value("map_uorder_0", glGetError());
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 31, &flat_patch[0][0][0]);
  conf_value("map_vorder_31", glGetError());
  glMapGrid2f(4, 0, 1, 0, 0, 1);
  conf_value("grid_zero", glGetError());
  glEvalMesh2(GL_LINE_STRIP, 0, 3, 0, 3);
  conf_value("mesh_bad_mode", glGetError());
  glGetMapfv(GL_MAP2_VERTEX_3, GL_RGBA, fv);
  conf_value("get_bad_query", glGetError());
  glBegin(GL_POINTS);
  glEvalMesh2(GL_FILL, 0, 3, 0, 3);
  glEnd();
  conf_value("mesh_in_begin", glGetError());
  glBegin(GL_POINTS);
  glMapGrid2f(4, 0, 1, 4, 0, 1);
  glEnd();
  conf_value("grid_in_begin", glGetError());
  glDeleteLists(list, 1);
  return conf_end();
}
