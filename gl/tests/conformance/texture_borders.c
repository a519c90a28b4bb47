/* Texture borders (border = 1): a 2-D image of 8x4 texels inside a ring of border
 * texels of other colours, drawn under GL_REPEAT, GL_CLAMP_TO_EDGE and
 * GL_MIRRORED_REPEAT with GL_NEAREST and GL_LINEAR (modes that never read the border:
 * the image must be read inside the ring) and GL_CLAMP with GL_NEAREST; a bordered 1-D
 * and 3-D texture; a bordered mip chain given by hand, minified; sub-images and copies
 * into the image; glCopyTexImage2D with a border from the framebuffer (piglit's
 * copyteximage-border). Compared with Mesa, which strips a texture's border when it is
 * given (gallium drivers keep none), so only what both agree on is compared: the image
 * inside, the sizes less twice GL_TEXTURE_BORDER, the errors. The border texels
 * themselves (kept, addressed at -1, read back) are checked against the spec by
 * gl_texture_border (gl/tests/limits/texture_border.c). */
#include "harness.h"

static void quad(float x, float y, float w, float h, float s0, float s1, float t0, float t1) {
  glBegin(GL_QUADS);
  glTexCoord3f(s0, t0, 0.4f);
  glVertex2f(x, y);
  glTexCoord3f(s1, t0, 0.4f);
  glVertex2f(x + w, y);
  glTexCoord3f(s1, t1, 0.4f);
  glVertex2f(x + w, y + h);
  glTexCoord3f(s0, t1, 0.4f);
  glVertex2f(x, y + h);
  glEnd();
}

/* Texel (x, y) of a w x h bordered image (the border at x or y = 0 and w - 1 / h - 1). */
static void fill(GLubyte* p, int w, int h, int seed) {
  int x, y;
  for (y = 0; y < h; ++y)
    for (x = 0; x < w; ++x) {
      GLubyte* t = p + 4 * (y * w + x);
      const int border = x == 0 || y == 0 || x == w - 1 || y == h - 1;
      t[0] = (GLubyte)(border ? 250 - 20 * (y % 4) : (x * 37 + seed * 50) % 200);
      t[1] = (GLubyte)(border ? 30 * (x % 5) : (y * 61 + seed * 20) % 256);
      t[2] = (GLubyte)(border ? 200 : (x * y * 13 + 40) % 180);
      t[3] = 255;
    }
}

/* A level's size less its border: the image's (Mesa strips borders: its GL_TEXTURE_BORDER is 0). */
static GLint inner(GLenum target, GLint level, GLenum size) {
  GLint n = 0, border = 0;
  glGetTexLevelParameteriv(target, level, size, &n);
  glGetTexLevelParameteriv(target, level, GL_TEXTURE_BORDER, &border);
  return n - 2 * border;
}

int main(int argc, char** argv) {
  static GLubyte image[18 * 18 * 18 * 4];
  GLuint tex[5];
  GLint iv = 0;
  int i;
  conf_init(argc, argv, 200, 160);
  conf_ortho();
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glGenTextures(5, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  /* Row 0: the 8x4 image in a 10x6 ring, each wrap mode that ignores the border. */
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  fill(image, 10, 6, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 10, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  conf_value("image_error", glGetError());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  {
    static const GLenum wraps[4] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT, GL_CLAMP};
    for (i = 0; i < 7; ++i) {
      const GLenum wrap = wraps[i % 4];
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)wrap);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)wrap);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, i < 4 ? GL_NEAREST : GL_LINEAR);
      quad(2.0f + 28 * (float)i, 2, 26, 26, -0.3f, 1.45f, -0.55f, 1.2f);
    }
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  conf_value("width", inner(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH));
  conf_value("height", inner(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT));

  /* Row 1: a sub-image over the top-left corner; a copy from the framebuffer into the
   * right column; drawn. */
  {
    GLubyte sub[3 * 3 * 4];
    for (i = 0; i < 9; ++i) sub[4 * i] = (GLubyte)(i * 28), sub[4 * i + 1] = 255, sub[4 * i + 2] = 0, sub[4 * i + 3] = 255;
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 3, 3, GL_RGBA, GL_UNSIGNED_BYTE, sub);
    conf_value("sub_error", glGetError());
  }
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 6, 0, 30, 10, 2, 4);
  conf_value("copy_sub_error", glGetError());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  quad(2, 32, 40, 24, 0, 1, 0, 1);
  /* A bordered mip chain (8x8 ... 1x1 inside), minified with the linear mipmap filter. */
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  for (i = 0; i <= 3; ++i) {
    const int n = (8 >> i) + 2;
    fill(image, n, n, i + 2);
    glTexImage2D(GL_TEXTURE_2D, i, GL_RGB, n, n, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  quad(46, 32, 60, 24, 0, 9.0f, 0, 3.0f);
  conf_value("level2_width", inner(GL_TEXTURE_2D, 2, GL_TEXTURE_WIDTH));
  glDisable(GL_TEXTURE_2D);

  /* A bordered 1-D texture (16 inside) and a 3-D one (4x4x4 inside), repeated. */
  glBindTexture(GL_TEXTURE_1D, tex[2]);
  fill(image, 18, 1, 5);
  for (i = 0; i < 4; ++i) image[i] = image[17 * 4 + i] = (GLubyte)(i == 1 ? 255 : 0); /* green ends */
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 18, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_1D);
  quad(110, 32, 40, 24, -0.2f, 1.3f, 0, 1);
  glDisable(GL_TEXTURE_1D);
  conf_value("width_1d", inner(GL_TEXTURE_1D, 0, GL_TEXTURE_WIDTH));
  glGetTexLevelParameteriv(GL_TEXTURE_1D, 0, GL_TEXTURE_HEIGHT, &iv);
  conf_value("height_1d", iv);
  glBindTexture(GL_TEXTURE_3D, tex[3]);
  fill(image, 6, 36, 6);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 6, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  conf_value("image_3d_error", glGetError());
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_3D);
  quad(154, 32, 40, 24, -0.1f, 1.6f, 0.2f, 2.3f);
  glDisable(GL_TEXTURE_3D);
  conf_value("depth_3d", inner(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH));

  /* Row 2: piglit's copyteximage-border: four colours copied with a 1-pixel border. */
  glColor3f(1, 0, 0);
  glRectf(10, 70, 42, 102);
  glColor3f(0, 1, 0);
  glRectf(42, 70, 74, 102);
  glColor3f(0, 0, 1);
  glRectf(10, 102, 42, 134);
  glColor3f(1, 1, 1);
  glRectf(42, 102, 74, 134);
  glBindTexture(GL_TEXTURE_2D, tex[4]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 9, 69, 66, 66, 1);
  conf_value("copy_error", glGetError());
  glEnable(GL_TEXTURE_2D);
  quad(84, 70, 64, 64, 0, 1, 0, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  quad(152, 70, 44, 64, -0.5f, 1.5f, 0, 1);
  glDisable(GL_TEXTURE_2D);
  conf_value("copy_width", inner(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH));
  conf_frame("bordered");

  /* Proxies with a border; errors. */
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 66, 34, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_value("proxy_width", inner(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH));
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 18, 10, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_value("proxy_3d_depth", inner(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_DEPTH));
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 10, 6, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
  conf_value("border_2", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 10, 6, -1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  conf_value("border_negative", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 10, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  conf_value("border_too_short", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 10, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glTexSubImage2D(GL_TEXTURE_2D, 0, -2, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
  conf_value("sub_past_border", glGetError());
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, -2, 0, 0, 2, 2);
  conf_value("copy_sub_past_border", glGetError());
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 2);
  conf_value("copy_border_2", glGetError());
  glDeleteTextures(5, tex);
  return conf_end();
}
