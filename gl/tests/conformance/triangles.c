/* Triangles with per-vertex colours, the depth test, and the matrix calls: glOrtho and
 * glFrustum / gluPerspective projections, translate, rotate, scale, push and pop. */
#include "harness.h"

static void colored_triangle(float z) {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex3f(-0.8f, -0.6f, z);
  glColor3f(0, 1, 0);
  glVertex3f(0.8f, -0.6f, z);
  glColor3f(0, 0, 1);
  glVertex3f(0.0f, 0.8f, z);
  glEnd();
}

int main(int argc, char** argv) {
  int i;
  conf_init(argc, argv, 160, 120);

  /* Orthographic, two overlapping triangles, the nearer one drawn first. */
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.333, 1.333, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  colored_triangle(0.2f);
  glPushMatrix();
  glTranslatef(0.3f, 0.1f, 0);
  glRotatef(180, 0, 0, 1);
  glScalef(0.7f, 0.7f, 1);
  colored_triangle(-0.2f);
  glPopMatrix();
  glColor3ub(255, 255, 0);
  glBegin(GL_TRIANGLES);
  glVertex2f(-1.2f, 0.9f);
  glVertex2f(-0.9f, 0.9f);
  glVertex2f(-1.05f, 0.6f);
  glEnd();
  conf_frame("ortho");

  /* Perspective: a ring of triangles at different depths, spun. */
  for (i = 0; i < 3; ++i) {
    int k;
    char name[32];
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (i == 0) glFrustum(-0.133, 0.133, -0.1, 0.1, 0.2, 20);
    else gluPerspective(50 + 10 * i, 160.0 / 120.0, 0.5, 30);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0, 1.5, 4, 0, 0, 0, 0, 1, 0);
    glRotatef(30.0f * i, 0, 1, 0);
    for (k = 0; k < 8; ++k) {
      glPushMatrix();
      glRotatef(45.0f * k, 0, 1, 0);
      glTranslatef(0, 0, 1.5f);
      glRotated(20.0 * k, 1, 0, 0);
      colored_triangle(0);
      glPopMatrix();
    }
    /* A big triangle cutting through the ring (depth intersections). */
    glBegin(GL_TRIANGLES);
    glColor4f(1, 1, 1, 1);
    glVertex3f(-3, -0.5f, -3);
    glColor4f(0.2f, 0.6f, 0.9f, 1);
    glVertex3f(3, 0.5f, -3);
    glColor4f(0.9f, 0.4f, 0.2f, 1);
    glVertex3f(0, 0, 3);
    glEnd();
    snprintf(name, sizeof name, "perspective%d", i);
    conf_frame(name);
  }

  /* Depth functions and the depth mask. */
  glClearDepth(0.5);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDepthFunc(GL_GREATER);
  colored_triangle(0.5f); /* window depth 0.75 > 0.5: drawn */
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glColor3f(1, 1, 1);
  glRectf(-0.2f, -0.2f, 0.2f, 0.2f); /* depth 0.5 < 0.75 at the triangle: drawn, not written */
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_ALWAYS);
  glColor3f(0.5f, 0, 0.5f);
  glRectf(0.5f, 0.5f, 0.9f, 0.9f);
  conf_frame("depth_funcs");
  return conf_end();
}
