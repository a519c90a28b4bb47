/* Line stipple: patterns and repeat factors on x- and y-major lines, GL_LINES
 * (the pattern starts again with each line), strips and loops (it goes on from segment
 * to segment), wide and smooth lines, a line clipped by the view volume and one under a
 * perspective, from a display list; glGet of the pattern and repeat
 * (the factor clamped to [1, 256]), glPushAttrib and the error inside glBegin/glEnd.
 * Independent lines go right and up: the pieces of a line going left or down differ
 * from llvmpipe's by a pixel at their ends (docs/gl.md, "Known differences"), as do
 * stippled polygon outlines, which are not compared. */
#include <math.h>

#include "harness.h"

#define W 128
#define H 96

int main(int argc, char** argv) {
  static const GLushort patterns[6] = {0x0f0f, 0xaaaa, 0x3c81, 0x00ff, 0xf731, 0x8001};
  GLint iv[2];
  int i;
  conf_init(argc, argv, W, H);
  conf_ortho();
  glClearColor(0.1f, 0.1f, 0.1f, 1);

  /* Independent lines: each pattern and factor, x- and y-major. */
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_LINE_STIPPLE);
  for (i = 0; i < 6; ++i) {
    glLineStipple(1 + i % 3, patterns[i]);
    glBegin(GL_LINES);
    glColor3f(1, (float)i / 5, 0), glVertex2f(3.5f, 4.5f + 7 * i), glVertex2f(120.5f, 9.5f + 7 * i);
    glColor3f(0, 1, (float)i / 5), glVertex2f(8.5f + 9 * i, 48.5f), glVertex2f(4.5f + 9 * i, 90.5f);
    glColor3f(0.5f, 0.5f, 1), glVertex2f(62.5f, 45.5f + 3 * i), glVertex2f(122.5f - 9 * i, 90.5f);
    glEnd();
  }
  conf_frame("lines");

  /* A strip and a loop (the counter goes on across segments), smooth, then wide. */
  glClear(GL_COLOR_BUFFER_BIT);
  glLineStipple(2, 0x1c47);
  glBegin(GL_LINE_STRIP);
  for (i = 0; i < 9; ++i) {
    glColor3f((float)i / 8, 1 - (float)i / 8, 0.5f);
    glVertex2f(6.5f + 14 * i, 10.5f + (i % 2 ? 30 : 0));
  }
  glEnd();
  glLineWidth(3);
  glLineStipple(3, 0x5f3b);
  glBegin(GL_LINE_LOOP);
  glColor3f(1, 1, 0), glVertex2f(10.5f, 55.5f);
  glColor3f(0, 1, 1), glVertex2f(117.5f, 60.5f);
  glColor3f(1, 0, 1), glVertex2f(100.5f, 90.5f);
  glColor3f(1, 1, 1), glVertex2f(20.5f, 85.5f);
  glEnd();
  glLineWidth(1);
  conf_frame("strip_loop_wide");

  /* Clipped by the view volume (the pattern counts from where the line enters), and
   * under a perspective with depth. */
  glClear(GL_COLOR_BUFFER_BIT);
  glLineStipple(1, 0x33f1);
  glBegin(GL_LINES);
  glColor3f(1, 0.5f, 0), glVertex2f(-40.5f, 20.5f), glVertex2f(100.5f, 30.5f);
  glColor3f(0, 0.5f, 1), glVertex2f(60.5f, -30.5f), glVertex2f(70.5f, 120.5f);
  glEnd();
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -0.75, 0.75, 2, 20);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -5);
  glRotatef(-60, 1, 0, 0);
  glLineStipple(2, 0xe4e4);
  glBegin(GL_LINES);
  for (i = 0; i < 5; ++i) {
    glColor3f(1, 1, (float)i / 4);
    glVertex3f(-1.8f + 0.9f * (float)i, -3, 0), glVertex3f(-1.8f + 0.9f * (float)i, 3, 0);
  }
  glEnd();
  conf_ortho();
  conf_frame("clipped_perspective");

  /* From a display list. */
  glClear(GL_COLOR_BUFFER_BIT);
  glLineStipple(1, 0xff3c);
  glNewList(1, GL_COMPILE);
  glBegin(GL_LINES);
  for (i = 0; i < 3; ++i) {
    glColor3f(1, (float)i / 2, 0.3f);
    glVertex2f(8.5f + 40 * i, 10.5f), glVertex2f(40.5f + 40 * i, 12.5f);
    glVertex2f(10.5f + 40 * i, 20.5f), glVertex2f(38.5f + 40 * i, 80.5f);
  }
  glEnd();
  glEndList();
  glCallList(1);
  conf_frame("list");

  /* State. */
  glLineStipple(0, 0x1234);
  glGetIntegerv(GL_LINE_STIPPLE_REPEAT, iv);
  conf_value("repeat_clamped_low", iv[0]);
  glLineStipple(300, 0xfedc);
  glGetIntegerv(GL_LINE_STIPPLE_REPEAT, iv);
  glGetIntegerv(GL_LINE_STIPPLE_PATTERN, iv + 1);
  conf_value("repeat_clamped_high", iv[0]);
  conf_value("pattern", iv[1]);
  conf_value("enabled", glIsEnabled(GL_LINE_STIPPLE));
  glPushAttrib(GL_LINE_BIT);
  glLineStipple(5, 0x00f0);
  glDisable(GL_LINE_STIPPLE);
  glPopAttrib();
  glGetIntegerv(GL_LINE_STIPPLE_REPEAT, iv);
  glGetIntegerv(GL_LINE_STIPPLE_PATTERN, iv + 1);
  conf_value("pop_line_repeat", iv[0]);
  conf_value("pop_line_pattern", iv[1]);
  conf_value("pop_line_enabled", glIsEnabled(GL_LINE_STIPPLE));
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_LINE_STIPPLE);
  glPopAttrib();
  conf_value("pop_enable_enabled", glIsEnabled(GL_LINE_STIPPLE));
  conf_value("error_none", glGetError());
  glBegin(GL_LINES);
  glLineStipple(1, 1);
  glEnd();
  conf_value("error_in_begin", glGetError());
  glGetIntegerv(GL_LINE_STIPPLE_PATTERN, iv);
  conf_value("pattern_after_error", iv[0]);
  return conf_end();
}
