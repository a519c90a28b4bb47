/* Lines where 2-D programs put them: gluOrtho2D(0, w, 0, h) and integer coordinates, so
 * that a line lies exactly on pixel boundaries, and GL's diamond-exit rule decides which
 * row or column it lights. Horizontal, vertical and diagonal lines in both directions,
 * a closed outline (GL_LINE_LOOP), a strip, lines through pixel centres, shallow and
 * steep ones, crossings exactly on a boundary each way round. Every row's and column's
 * count of lit pixels is a value, compared exactly with Mesa's; the frames by PSNR.
 * (Left out: a line going left and down that ends exactly on a boundary at a pixel
 * centre, after another line in the same frame; Mesa then lights its end pixel too,
 * docs/gl.md.) */
#include "harness.h"

enum { W = 48, H = 40 };

/* Lit pixels per row and per column, as values NAME_rY and NAME_cX. */
static void profile(const char* name) {
  static GLubyte px[W * H * 4];
  int counts_r[H] = {0}, counts_c[W] = {0};
  char n[64];
  int x, y;
  glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
  for (y = 0; y < H; ++y)
    for (x = 0; x < W; ++x)
      if (px[(y * W + x) * 4] > 127) ++counts_r[y], ++counts_c[x];
  for (y = 0; y < H; ++y) {
    snprintf(n, sizeof n, "%s_r%d", name, y);
    conf_value(n, counts_r[y]);
  }
  for (x = 0; x < W; ++x) {
    snprintf(n, sizeof n, "%s_c%d", name, x);
    conf_value(n, counts_c[x]);
  }
  conf_frame(name);
}

static void line(float x0, float y0, float x1, float y1) {
  glBegin(GL_LINES);
  glVertex2f(x0, y0);
  glVertex2f(x1, y1);
  glEnd();
}

int main(int argc, char** argv) {
  conf_init(argc, argv, W, H);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, W, 0, H);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0, 0, 0, 1);
  glColor3f(1, 1, 1);

  /* On pixel boundaries: horizontal and vertical, each way round. */
  glClear(GL_COLOR_BUFFER_BIT);
  line(5, 10, 30, 10);
  line(33, 14, 8, 14);
  line(20, 3, 20, 25);
  line(40, 30, 40, 5);
  profile("axis");

  /* A closed outline and a strip with integer corners. */
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_LINE_LOOP);
  glVertex2i(4, 4);
  glVertex2i(30, 4);
  glVertex2i(30, 22);
  glVertex2i(4, 22);
  glEnd();
  glBegin(GL_LINE_STRIP);
  glVertex2i(34, 2);
  glVertex2i(44, 2);
  glVertex2i(44, 36);
  glVertex2i(34, 30);
  glEnd();
  profile("outline");

  /* Diagonals (45 degrees, all four directions), shallow and steep lines. */
  glClear(GL_COLOR_BUFFER_BIT);
  line(2, 2, 18, 18);
  line(40, 20, 24, 36);
  line(44, 2, 28, 18);
  line(2, 36, 14, 24);
  line(3, 20, 21, 25);
  line(25, 2, 29, 17);
  profile("diagonal");

  /* Through pixel centres (half-integer coordinates). */
  glClear(GL_COLOR_BUFFER_BIT);
  line(3.5f, 5.5f, 30.5f, 5.5f);
  line(10.5f, 8.5f, 10.5f, 35.5f);
  line(14.5f, 10.5f, 40.5f, 33.5f);
  profile("centres");

  /* Crossings exactly on a pixel boundary at pixel centres, each way round: rising,
   * falling, x-major and y-major, starting on the boundary or ending there. */
  glClear(GL_COLOR_BUFFER_BIT);
  line(0.5f, 10.5f, 4.5f, 12.5f);
  line(6.5f, 10, 10.5f, 12);
  line(18.5f, 12, 22.5f, 10);
  line(28.5f, 10, 24.5f, 12);
  line(30, 0.5f, 32, 4.5f);
  line(36, 0.5f, 34, 4.5f);
  line(40, 4.5f, 38, 0.5f);
  line(44, 8.5f, 46, 4.5f);
  line(2.5f, 30, 12.5f, 25);
  line(14.5f, 25, 24.5f, 30);
  line(30, 20.5f, 35, 30.5f);
  line(42, 30.5f, 37, 20.5f);
  profile("ties");
  return conf_end();
}
