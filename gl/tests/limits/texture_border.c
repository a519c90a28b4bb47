/* Texture borders as GL 1.5 section 3.8.1 says, where Mesa is no oracle (it strips a
 * border when one is given): the sizes glGetTexLevelParameter returns are the sizes as
 * specified, border included, and GL_TEXTURE_BORDER is 1; glGetTexImage returns the
 * whole image, border included; glTexSubImage2D and glCopyTexSubImage2D address the
 * border at -1 and may write it; an offset past it is GL_INVALID_VALUE. The expected
 * texels are the ones given (each distinct), the sizes the spec's. Fails with a line
 * naming the first difference. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <string.h>

static int failures = 0;

static void expect(const char* what, long got, long want) {
  if (got == want) return;
  fprintf(stderr, "texture_border: %s is %ld, expected %ld\n", what, got, want);
  ++failures;
}

static GLint level_value(GLenum target, GLenum pname) {
  GLint v = -1;
  glGetTexLevelParameteriv(target, 0, pname, &v);
  return v;
}

int main(void) {
  static unsigned char buffer[16 * 16 * 4];
  static GLubyte image[6 * 5 * 4], back[6 * 6 * 6 * 4], volume[4 * 4 * 4 * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 16, 16)) return 2;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);

  /* A 4x3 image in a border: 6x5 texels, texel (x, y) red 10 x + y, green 100 + x. */
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 6; ++x) {
      GLubyte* t = image + 4 * (y * 6 + x);
      t[0] = (GLubyte)(10 * x + y), t[1] = (GLubyte)(100 + x), t[2] = 7, t[3] = 255;
    }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 6, 5, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  expect("glTexImage2D's error", glGetError(), GL_NO_ERROR);
  expect("GL_TEXTURE_WIDTH", level_value(GL_TEXTURE_2D, GL_TEXTURE_WIDTH), 6);
  expect("GL_TEXTURE_HEIGHT", level_value(GL_TEXTURE_2D, GL_TEXTURE_HEIGHT), 5);
  expect("GL_TEXTURE_BORDER", level_value(GL_TEXTURE_2D, GL_TEXTURE_BORDER), 1);
  memset(back, 0, sizeof back);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  for (int i = 0; i < 6 * 5 * 4 && !failures; ++i) expect("a texel read back (glGetTexImage)", back[i], image[i]);

  /* The border's bottom-left corner and its neighbours, at -1. */
  {
    const GLubyte sub[2 * 2 * 4] = {201, 0, 0, 255, 202, 0, 0, 255, 203, 0, 0, 255, 204, 0, 0, 255};
    glTexSubImage2D(GL_TEXTURE_2D, 0, -1, -1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, sub);
    expect("glTexSubImage2D at -1's error", glGetError(), GL_NO_ERROR);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    expect("border texel (0, 0)", back[0], 201);
    expect("border texel (1, 0)", back[4], 202);
    expect("image texel (1, 1)", back[4 * 7], 204);
    expect("texel (2, 1), untouched", back[4 * 8], 21);
  }
  glTexSubImage2D(GL_TEXTURE_2D, 0, -2, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  expect("glTexSubImage2D past the border", glGetError(), GL_INVALID_VALUE);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  expect("glTexSubImage2D at the top-right border texel", glGetError(), GL_NO_ERROR);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 3, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  expect("glTexSubImage2D past the right border", glGetError(), GL_INVALID_VALUE);

  /* A framebuffer pixel copied into the border's top-right texel. */
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 4, 3, 5, 5, 1, 1);
  expect("glCopyTexSubImage2D into the border's error", glGetError(), GL_NO_ERROR);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  expect("copied border texel (5, 4) green", back[4 * (4 * 6 + 5) + 1], 255);
  expect("copied border texel (5, 4) red", back[4 * (4 * 6 + 5)], 0);

  /* 1-D: 16 texels in a border of 2 (18 given); height 1, no border rows. */
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 18, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  expect("GL_TEXTURE_WIDTH (1-D)", level_value(GL_TEXTURE_1D, GL_TEXTURE_WIDTH), 18);
  expect("GL_TEXTURE_HEIGHT (1-D)", level_value(GL_TEXTURE_1D, GL_TEXTURE_HEIGHT), 1);
  glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  expect("1-D border texel 17", back[4 * 17], image[4 * 17]);
  expect("1-D border texel 0", back[0], image[0]);

  /* 3-D: 2x2x2 in a border, 4x4x4 given. */
  for (int i = 0; i < 4 * 4 * 4 * 4; ++i) volume[i] = (GLubyte)(i * 7 + 3);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, volume);
  expect("glTexImage3D's error", glGetError(), GL_NO_ERROR);
  expect("GL_TEXTURE_DEPTH", level_value(GL_TEXTURE_3D, GL_TEXTURE_DEPTH), 4);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
  for (int i = 0; i < 4 * 4 * 4 * 4 && !failures; ++i) expect("a 3-D texel read back", back[i], volume[i]);

  /* Borders other than 0 and 1; a border around nothing. */
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 6, 5, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
  expect("border 2", glGetError(), GL_INVALID_VALUE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 5, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  expect("border 1 around width -1", glGetError(), GL_INVALID_VALUE);
  OSMesaDestroyContext(ctx);
  if (failures) return 1;
  printf("texture_border: every size and texel as the spec says\n");
  return 0;
}
