/* User clip planes: glClipPlane (taken through the modelview matrix of its time into
 * eye space), enabled one to six at a time, cutting filled triangles, quads and a fan
 * (smooth colours interpolated to the cut), lines, wide lines, polygon-mode lines and
 * points (dropped whole), together with the near plane, in a display list; the raster
 * position; glGetClipPlane, glIsEnabled, GL_MAX_CLIP_PLANES and the errors. */
#include <math.h>

#include "harness.h"

#define W 120
#define H 90

static void values(const char* name, GLenum pname, int n) {
  GLdouble v[4];
  char k[80];
  int i;
  glGetDoublev(pname, v);
  for (i = 0; i < n; ++i) {
    snprintf(k, sizeof k, "%s_%d", name, i);
    conf_value(k, v[i]);
  }
}

static void plane_values(const char* name, GLenum plane) {
  GLdouble v[4];
  char k[80];
  int i;
  glGetClipPlane(plane, v);
  for (i = 0; i < 4; ++i) {
    snprintf(k, sizeof k, "%s_%d", name, i);
    conf_value(k, v[i]);
  }
}

/* Triangles (each one's colours are affine across it: quads with four unrelated
 * colours interpolate differently in Mesa, clipped or not). */
static void grid(void) {
  int i, j;
  glBegin(GL_TRIANGLES);
  for (j = 0; j < 6; ++j)
    for (i = 0; i < 8; ++i) {
      float x = -2 + 0.5f * (float)i, y = -1.5f + 0.5f * (float)j;
      glColor3f((float)i / 7, (float)j / 5, 0.5f);
      glVertex3f(x, y, 0);
      glColor3f(1, (float)j / 5, (float)i / 7);
      glVertex3f(x + 0.5f, y, 0);
      glColor3f(0.2f, 1, (float)(i + j) / 12);
      glVertex3f(x + 0.5f, y + 0.5f, 0);
      glColor3f((float)j / 5, 0.3f, 1);
      glVertex3f(x, y + 0.5f, 0);
      glColor3f(0.1f, 0.9f, 0.4f);
      glVertex3f(x, y, 0);
      glColor3f(0.2f, 1, (float)(i + j) / 12);
      glVertex3f(x + 0.5f, y + 0.5f, 0);
    }
  glEnd();
}

static void scene(void) {
  static const GLdouble diagonal[4] = {1, 1, 0, 0.3}, left[4] = {-1, 0, 0, 1.2};
  int i;
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -0.75, 0.75, 2, 20);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  /* Planes given under a rotation and a translation: kept in eye space. */
  glPushMatrix();
  glRotatef(25, 0, 0, 1);
  glClipPlane(GL_CLIP_PLANE0, diagonal);
  glPopMatrix();
  glPushMatrix();
  glTranslatef(0.4f, 0, -5);
  glClipPlane(GL_CLIP_PLANE3, left);
  glPopMatrix();
  glEnable(GL_CLIP_PLANE0);
  glEnable(GL_CLIP_PLANE3);
  glTranslatef(0, 0, -5);
  glRotatef(-30, 1, 0, 0);
  glRotatef(15, 0, 1, 0);
  grid();
  conf_frame("filled");
  plane_values("plane0", GL_CLIP_PLANE0);
  plane_values("plane3", GL_CLIP_PLANE3);

  /* Lines, wide lines, a fan, points; one plane off. */
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_CLIP_PLANE3);
  glBegin(GL_LINES);
  for (i = 0; i < 12; ++i) {
    float a = (float)i * 0.52f;
    glColor3f(1, (float)i / 11, 0);
    glVertex3f(0, 0, 0);
    glColor3f(0, 0.5f, 1);
    glVertex3f(2.2f * cosf(a), 1.6f * sinf(a), 0);
  }
  glEnd();
  glLineWidth(3);
  glBegin(GL_LINE_LOOP);
  glColor3f(1, 1, 1);
  glVertex3f(-1.75f, -1.2f, 0.2f);
  glVertex3f(1.8f, -1.2f, 0.2f);
  glVertex3f(1.8f, 1.2f, 0.2f);
  glVertex3f(-1.75f, 1.2f, 0.2f);
  glEnd();
  glLineWidth(1);
  glPointSize(3);
  glBegin(GL_POINTS);
  for (i = 0; i < 40; ++i) {
    glColor3f(0.5f, 1, 0.5f);
    glVertex3f(-2 + 0.1f * (float)i, 0.9f - 0.03f * (float)i, 0.1f);
  }
  glEnd();
  glPointSize(1);
  conf_frame("lines_points");

  /* All six, with the near plane cutting too (triangles reaching behind the eye), in
   * a display list, and a fan. */
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glLoadIdentity();
  for (i = 0; i < 6; ++i) {
    GLdouble eq[4];
    float a = (float)i * 1.047f + 0.2f;
    eq[0] = cosf(a), eq[1] = sinf(a), eq[2] = 0, eq[3] = 0.9 + 0.1 * i;
    glClipPlane(GL_CLIP_PLANE0 + i, eq);
    glEnable(GL_CLIP_PLANE0 + i);
  }
  glNewList(1, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex3f(-3, -0.6f, 1);
  glColor3f(0, 1, 0);
  glVertex3f(3, -0.6f, 1);
  glColor3f(0, 0, 1);
  glVertex3f(3, -0.6f, -12);
  glColor3f(1, 1, 0);
  glVertex3f(-3, -0.3f, -12);
  glColor3f(1, 0, 1);
  glVertex3f(-2, -0.3f, 1);
  glColor3f(0, 1, 1);
  glVertex3f(2.5f, -0.3f, -11);
  glEnd();
  glEndList();
  glCallList(1);
  glTranslatef(0, 0, -6);
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(1, 1, 1);
  glVertex3f(0, 0.3f, 0);
  for (i = 0; i <= 10; ++i) {
    glColor3f((float)i / 10, 0.5f, 1 - (float)i / 10);
    glVertex3f(2.5f * cosf((float)i * 0.628f), 0.3f + 2.0f * sinf((float)i * 0.628f), 0);
  }
  glEnd();
  conf_frame("six");
  conf_value("enabled2", glIsEnabled(GL_CLIP_PLANE2));
  for (i = 0; i < 6; ++i) glDisable(GL_CLIP_PLANE0 + i);
  conf_value("disabled2", glIsEnabled(GL_CLIP_PLANE2));
}

static void raster_and_errors(void) {
  static const GLdouble right_half[4] = {1, 0, 0, 0};
  GLdouble eq[4] = {1, 2, 3, 4};
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClipPlane(GL_CLIP_PLANE1, right_half);
  glEnable(GL_CLIP_PLANE1);
  glRasterPos2f(0.5f, 0);
  values("raster_inside_valid", GL_CURRENT_RASTER_POSITION_VALID, 1);
  glRasterPos2f(-0.5f, 0);
  values("raster_outside_valid", GL_CURRENT_RASTER_POSITION_VALID, 1);
  glDisable(GL_CLIP_PLANE1);
  {
    /* (pGL has 6, the least GL allows; Mesa 8.) */
    GLint max = 0;
    glGetIntegerv(GL_MAX_CLIP_PLANES, &max);
    conf_value("max_clip_planes_at_least_6", max >= 6);
  }
  conf_value("error_none", glGetError());
  glClipPlane(GL_CLIP_PLANE0 + 8, eq);
  conf_value("error_clip_plane_enum", glGetError());
  glGetClipPlane(GL_CLIP_PLANE0 - 1, eq);
  conf_value("error_get_clip_plane_enum", glGetError());
  glEnable(GL_CLIP_PLANE0 + 8);
  conf_value("error_enable_plane8", glGetError());
  glBegin(GL_TRIANGLES);
  glClipPlane(GL_CLIP_PLANE0, eq);
  glEnd();
  conf_value("error_in_begin", glGetError());
  plane_values("plane0_unchanged", GL_CLIP_PLANE0);
}

int main(int argc, char** argv) {
  conf_init(argc, argv, W, H);
  glEnable(GL_DEPTH_TEST);
  scene();
  raster_and_errors();
  return conf_end();
}
