/* GLU quadrics: gluSphere, gluCylinder (a cylinder and a cone), gluDisk and
 * gluPartialDisk in every draw style (fill, line, silhouette, point), smooth, flat and
 * no normals, outside and inside orientation, with and without texture coordinates,
 * lit and textured; and GLU's errors through the GLU_ERROR callback (GL's error state
 * untouched). Against Mesa, libGLU draws the same calls. */
#include "harness.h"

static int glu_errors[4];
static int glu_error_count;

static void GLAPIENTRY on_error(GLenum error) {
  if (glu_error_count < 4) glu_errors[glu_error_count] = (int)error;
  ++glu_error_count;
}

static unsigned char checker[16 * 8 * 4];

static void setup_texture(void) {
  int x, y;
  for (y = 0; y < 8; ++y)
    for (x = 0; x < 16; ++x) {
      unsigned char* p = checker + 4 * (y * 16 + x);
      const int on = (x / 2 + y / 2) % 2;
      p[0] = on ? 240 : (unsigned char)(20 + 14 * x), p[1] = on ? 220 : 40, p[2] = (unsigned char)(30 + 25 * y);
      p[3] = 255;
    }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

static void lights(int on) {
  const GLfloat pos[4] = {0.6f, 0.8f, 1.0f, 0}, diffuse[4] = {0.9f, 0.8f, 0.6f, 1}, amb[4] = {0.2f, 0.2f, 0.25f, 1};
  if (!on) {
    glDisable(GL_LIGHTING);
    return;
  }
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
}

/* A view of the four shapes side by side, each turned so that its asymmetries show. */
static void begin_frame(void) {
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  lights(1);
}

static void place(float x, float y) {
  glLoadIdentity();
  glTranslatef(x, y, -7);
  glRotatef(-60, 1, 0, 0);
  glRotatef(25, 0, 0, 1);
}

static void shapes(GLUquadric* q) {
  place(-1.8f, 0.9f);
  gluSphere(q, 0.8, 14, 9);
  place(0.2f, 0.6f);
  gluCylinder(q, 0.6, 0.6, 1.2, 11, 3);
  place(1.9f, 0.6f);
  gluCylinder(q, 0.7, 0.0, 1.3, 13, 2); /* a cone */
  place(-1.5f, -1.3f);
  gluDisk(q, 0.3, 0.9, 12, 3);
  place(0.4f, -1.3f);
  gluDisk(q, 0.0, 0.8, 10, 2);
  place(2.0f, -1.3f);
  gluPartialDisk(q, 0.2, 0.9, 9, 2, 30, -250); /* a negative sweep turns back */
}

int main(int argc, char** argv) {
  GLUquadric* q;
  static const GLenum styles[4] = {GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT};
  static const GLenum normals[3] = {GLU_SMOOTH, GLU_FLAT, GLU_NONE};
  int s, n;
  conf_init(argc, argv, 240, 180);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45, 240.0 / 180.0, 1, 20);
  setup_texture();
  q = gluNewQuadric();
  if (!q) conf_fail("gluNewQuadric failed");
  gluQuadricCallback(q, GLU_ERROR, (_GLUfuncptr)on_error);

  /* Every style with each kind of normal, lit (flat and none: whatever normal GLU
   * leaves current is part of the picture). */
  for (s = 0; s < 4; ++s)
    for (n = 0; n < 3; ++n) {
      char name[48];
      /* Flat normals with points or a silhouette: Mesa's GLU reads its smooth-normal
       * tables without filling them (an uninitialised read), so no image to match. */
      if ((styles[s] == GLU_POINT || styles[s] == GLU_SILHOUETTE) && normals[n] == GLU_FLAT) continue;
      begin_frame();
      glNormal3f(0.3f, 0.5f, 0.8f);
      glColor3f(1, 1, 1);
      glPointSize(2);
      gluQuadricDrawStyle(q, styles[s]);
      gluQuadricNormals(q, normals[n]);
      shapes(q);
      snprintf(name, sizeof name, "style%d_normals%d", s, n);
      conf_frame(name);
    }

  /* Inside orientation: the fronts face in (back faces culled, so the inner side shows). */
  gluQuadricDrawStyle(q, GLU_FILL);
  gluQuadricNormals(q, GLU_SMOOTH);
  gluQuadricOrientation(q, GLU_INSIDE);
  glEnable(GL_CULL_FACE);
  begin_frame();
  shapes(q);
  conf_frame("inside_culled");
  gluQuadricNormals(q, GLU_FLAT);
  begin_frame();
  shapes(q);
  conf_frame("inside_flat");
  glDisable(GL_CULL_FACE);

  /* Textured, unlit, both orientations: every shape's texture coordinates. */
  gluQuadricNormals(q, GLU_SMOOTH);
  gluQuadricTexture(q, GL_TRUE);
  glEnable(GL_TEXTURE_2D);
  for (n = 0; n < 2; ++n) {
    begin_frame();
    lights(0);
    glColor3f(1, 1, 1);
    gluQuadricOrientation(q, n ? GLU_INSIDE : GLU_OUTSIDE);
    shapes(q);
    conf_frame(n ? "textured_inside" : "textured_outside");
  }
  /* Textured and lit, lines and points. */
  gluQuadricOrientation(q, GLU_OUTSIDE);
  for (s = 1; s < 4; ++s) {
    char name[32];
    begin_frame();
    gluQuadricDrawStyle(q, styles[s]);
    shapes(q);
    snprintf(name, sizeof name, "textured_style%d", s);
    conf_frame(name);
  }
  glDisable(GL_TEXTURE_2D);
  gluQuadricTexture(q, GL_FALSE);

  /* Errors: GLU's, to the callback; nothing drawn, GL's error state untouched. */
  gluQuadricDrawStyle(q, GLU_FILL);
  begin_frame();
  gluQuadricNormals(q, GL_TRIANGLES);
  gluQuadricDrawStyle(q, GLU_SMOOTH);
  gluSphere(q, 1, 1, 4);
  gluCylinder(q, 0, 0, 0, 8, 2);
  conf_value("glu_error_count", glu_error_count);
  conf_value("glu_error_0", glu_errors[0]);
  conf_value("glu_error_1", glu_errors[1]);
  conf_value("glu_error_2", glu_errors[2]);
  conf_value("glu_error_3", glu_errors[3]);
  gluPartialDisk(q, 1, 0.5, 8, 2, 0, 90);
  gluDisk(q, 0, 1, 8, 0);
  gluCylinder(q, -1, 1, 1, 8, 2);
  conf_value("glu_error_count_after", glu_error_count);
  conf_value("gl_error", glGetError());
  conf_frame("after_errors");
  gluDeleteQuadric(q);
  return conf_end();
}
