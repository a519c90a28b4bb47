/* Feedback: glRenderMode(GL_FEEDBACK) with glFeedbackBuffer's five types and
 * glPassThrough: points, lines (strips, independent, clipped), triangles, a quad, a
 * polygon cut by the view volume, fans, strips, quad strips, a culled face, flat shading, a perspective view with texture coordinates, and the raster
 * position's tokens (glBitmap, glDrawPixels, glCopyPixels); an asymmetric viewport and
 * depth range. Every value written is compared with Mesa's (to 1/100), as are the
 * counts glRenderMode returns, an overflowing buffer, the queries and GL's errors. */
#include <math.h>

#include "harness.h"

static GLfloat buf[1024];

static void error(const char* name) { conf_value(name, glGetError()); }

static void values(const char* name, GLint count) {
  char n[64];
  GLint i;
  snprintf(n, sizeof n, "%s_count", name);
  conf_value(n, count);
  for (i = 0; i < count && i < 1024; ++i) {
    snprintf(n, sizeof n, "%s_%d", name, i);
    conf_value(n, floor(buf[i] * 100 + 0.5) / 100);
  }
}

static void scene(void) {
  /* Two rows of a 3-wide bitmap: GL_UNPACK_ALIGNMENT is 4, so the second row starts at
   * byte 4, not byte 1. */
  static const GLubyte bits[8] = {0xa0, 0, 0, 0, 0x40, 0, 0, 0};
  static const GLubyte pixels[4 * 6] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255,
                                        9, 9, 9, 255, 90, 90, 90, 255, 200, 100, 0, 255};
  glBegin(GL_POINTS);
  glColor4f(1, 0.5f, 0.25f, 0.75f);
  glTexCoord4f(0.1f, 0.2f, 0.3f, 1);
  glVertex3f(0.25f, 0.5f, 0.3f);
  glVertex3f(3, 0, 0); /* outside */
  glEnd();
  glPassThrough(17.5f);
  glBegin(GL_LINE_STRIP); /* the second segment leaves through the right */
  glColor3f(0, 1, 0);
  glVertex3f(-0.5f, -0.5f, 0);
  glColor3f(0, 0, 1);
  glVertex3f(0.5f, -0.25f, 0.5f);
  glColor3f(1, 0, 0);
  glVertex3f(1.5f, 0.75f, -0.5f);
  glEnd();
  glBegin(GL_LINES);
  glVertex2f(-0.9f, 0.9f);
  glVertex2f(-0.1f, 0.8f);
  glVertex2f(-0.9f, -0.9f);
  glVertex2f(-0.3f, -0.7f);
  glEnd();
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex3f(-0.75f, -0.5f, -0.25f);
  glColor3f(0, 1, 0);
  glVertex3f(0.5f, -0.75f, 0.25f);
  glColor3f(0, 0, 1);
  glVertex3f(0.1f, 0.6f, 0.75f);
  /* clockwise: back-facing, drawn (culling is off here) */
  glVertex2f(-0.2f, 0.2f);
  glVertex2f(-0.1f, 0.4f);
  glVertex2f(0, 0.2f);
  glEnd();
  glBegin(GL_POLYGON); /* five vertices, cut by the top and the left of the volume */
  glColor3f(1, 1, 0);
  glVertex2f(-1.5f, 0.2f);
  glVertex2f(0.2f, 0.1f);
  glColor3f(0, 1, 1);
  glVertex2f(0.4f, 0.8f);
  glVertex2f(0, 1.6f);
  glColor3f(1, 0, 1);
  glVertex2f(-0.8f, 1.2f);
  glEnd();
  glRectf(0.6f, 0.6f, 0.8f, 0.9f);
  glShadeModel(GL_FLAT);
  glBegin(GL_QUADS);
  glColor3f(1, 0, 0);
  glVertex2f(0.2f, -0.9f);
  glColor3f(0, 1, 0);
  glVertex2f(0.9f, -0.9f);
  glColor3f(0, 0, 1);
  glVertex2f(0.9f, -0.3f);
  glColor3f(1, 1, 1);
  glVertex2f(0.2f, -0.4f);
  glEnd();
  glShadeModel(GL_SMOOTH);
  glBegin(GL_TRIANGLE_FAN);
  glColor3f(0.5f, 0.25f, 1);
  glVertex2f(-0.6f, 0);
  glVertex2f(-0.2f, 0.05f);
  glColor3f(0.25f, 1, 0.5f);
  glVertex2f(-0.4f, 0.3f);
  glVertex2f(-0.7f, 0.4f);
  glEnd();
  glBegin(GL_TRIANGLE_STRIP);
  glVertex2f(0.3f, 0.1f);
  glVertex2f(0.5f, 0.1f);
  glVertex2f(0.3f, 0.3f);
  glVertex2f(0.6f, 0.35f);
  glEnd();
  glBegin(GL_QUAD_STRIP);
  glColor3f(0.75f, 0.5f, 0.25f);
  glVertex2f(-0.9f, -0.3f);
  glVertex2f(-0.7f, -0.3f);
  glVertex2f(-0.9f, -0.1f);
  glVertex2f(-0.65f, -0.15f);
  glEnd();
  glEnable(GL_CULL_FACE);
  glBegin(GL_TRIANGLES); /* clockwise: culled */
  glVertex2f(0, 0);
  glVertex2f(0, 0.5f);
  glVertex2f(0.5f, 0);
  glEnd();
  glDisable(GL_CULL_FACE);
  glColor3f(0.2f, 0.4f, 0.6f);
  glRasterPos3f(-0.5f, 0.25f, 0.5f);
  glBitmap(3, 2, 0, 0, 4, 1, bits);
  glDrawPixels(3, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  glCopyPixels(0, 0, 4, 4, GL_COLOR);
  glRasterPos2f(5, 5); /* invalid: no token */
  glBitmap(3, 2, 0, 0, 4, 1, bits);
  glPassThrough(-2);
}

int main(int argc, char** argv) {
  GLint v;
  conf_init(argc, argv, 64, 48);
  glGetIntegerv(GL_FEEDBACK_BUFFER_TYPE, &v);
  conf_value("initial_type", v);
  conf_value("feedback_without_buffer", glRenderMode(GL_FEEDBACK));
  error("feedback_without_buffer_error");
  glRenderMode(GL_RENDER); /* (Mesa enters feedback mode anyway) */
  glFeedbackBuffer(16, GL_RGB, buf);
  error("bad_type");
  glFeedbackBuffer(-1, GL_2D, buf);
  error("negative_size");

  glViewport(5, 3, 50, 40);
  glDepthRange(0.2, 0.9);
  {
    static const GLenum types[5] = {GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE};
    static const char* names[5] = {"2d", "3d", "3d_color", "3d_color_texture", "4d_color_texture"};
    int t;
    for (t = 0; t < 5; ++t) {
      glFeedbackBuffer(1024, types[t], buf);
      glGetIntegerv(GL_FEEDBACK_BUFFER_SIZE, &v);
      conf_value("buffer_size", v);
      glGetIntegerv(GL_FEEDBACK_BUFFER_TYPE, &v);
      conf_value("buffer_type", v);
      conf_value("enter", glRenderMode(GL_FEEDBACK));
      glGetIntegerv(GL_RENDER_MODE, &v);
      conf_value("mode", v);
      glFeedbackBuffer(1024, GL_2D, buf);
      error("buffer_in_feedback");
      scene();
      values(names[t], glRenderMode(GL_RENDER));
      error(names[t]);
    }
  }

  /* A perspective view with a texture matrix, clipped by the near plane. */
  glMatrixMode(GL_PROJECTION);
  gluPerspective(60, 1.25, 1, 10);
  glMatrixMode(GL_TEXTURE);
  glScalef(2, 0.5f, 1);
  glMatrixMode(GL_MODELVIEW);
  { /* A complete texture: without one, Mesa reports the coordinates untransformed. */
    static const GLubyte texel[4] = {255, 255, 255, 255};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
  }
  glFeedbackBuffer(1024, GL_4D_COLOR_TEXTURE, buf);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_QUADS);
  glColor3f(1, 0.5f, 0);
  glTexCoord2f(0, 0);
  glVertex3f(-1, -1, 0);
  glTexCoord2f(1, 0);
  glVertex3f(1, -1, 0);
  glTexCoord2f(1, 1);
  glVertex3f(1, 1, -6);
  glTexCoord2f(0, 1);
  glVertex3f(-1, 1, -6);
  glEnd();
  values("perspective", glRenderMode(GL_RENDER));
  glDisable(GL_TEXTURE_2D);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);

  /* Overflow: -1, and nothing written past the size. */
  buf[6] = 123;
  glFeedbackBuffer(6, GL_3D, buf);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(0.5f, 0);
  glVertex2f(0, 0.5f);
  glEnd();
  conf_value("overflow", glRenderMode(GL_RENDER));
  conf_value("past_the_end", buf[6]);
  glPassThrough(1); /* in GL_RENDER: ignored */
  error("render_pass_through");
  glBegin(GL_POINTS);
  glPassThrough(1);
  glEnd();
  error("pass_through_in_begin");

  /* Drawing again after feedback. */
  glViewport(0, 0, 64, 48);
  glDepthRange(0, 1);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 0.5f, 0);
  glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
  conf_frame("after");
  return conf_end();
}
