/* 1-D textures: glTexImage1D (RGB, RGBA, LUMINANCE; a non-power-of-two width), each
 * level of a mip chain given by hand, magnified with GL_NEAREST and GL_LINEAR under
 * GL_REPEAT, GL_CLAMP_TO_EDGE and GL_MIRRORED_REPEAT, minified with the mipmap filters,
 * with t varying wildly (a 1-D texture does not read it) and through the texture
 * matrix; glTexSubImage1D; glCopyTexImage1D and glCopyTexSubImage1D from a row of the
 * framebuffer; GL_TEXTURE_2D taking precedence over GL_TEXTURE_1D; in a display list.
 * Values: glGetTexImage, glGetTexLevelParameteriv, GL_TEXTURE_BINDING_1D, glIsEnabled,
 * glPushAttrib, the errors. Compared with Mesa. */
#include "harness.h"

static GLubyte ramp[37 * 4];

static void quad(float x0, float y0, float x1, float y1, float s0, float s1) {
  glBegin(GL_QUADS);
  glTexCoord2f(s0, -3.0f);
  glVertex2f(x0, y0);
  glTexCoord2f(s1, 5.0f);
  glVertex2f(x1, y0);
  glTexCoord2f(s1, 0.25f);
  glVertex2f(x1, y1);
  glTexCoord2f(s0, 12.0f);
  glVertex2f(x0, y1);
  glEnd();
}

int main(int argc, char** argv) {
  GLuint tex[3];
  GLint iv = 0;
  int i;
  conf_init(argc, argv, 160, 128);
  conf_ortho();
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  for (i = 0; i < 37; ++i) {
    ramp[4 * i] = (GLubyte)(7 * i), ramp[4 * i + 1] = (GLubyte)(i % 5 * 60), ramp[4 * i + 2] = (GLubyte)(255 - 6 * i);
    ramp[4 * i + 3] = (GLubyte)(i % 3 ? 255 : 120);
  }
  glGenTextures(3, tex);
  glBindTexture(GL_TEXTURE_1D, tex[0]);
  glGetIntegerv(GL_TEXTURE_BINDING_1D, &iv);
  conf_value("binding_1d", iv == (GLint)tex[0]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 37, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_1D);
  conf_value("enabled_1d", glIsEnabled(GL_TEXTURE_1D));
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  /* Row 0: magnified, nearest and linear, three wrap modes, s from -0.6 to 1.4. */
  {
    static const GLenum wraps[3] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT};
    for (i = 0; i < 6; ++i) {
      glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, (GLint)wraps[i % 3]);
      glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, i < 3 ? GL_NEAREST : GL_LINEAR);
      quad(2.0f + 26 * (float)i, 2, 26.0f + 26 * (float)i, 60, -0.6f, 1.4f);
    }
  }
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_REPEAT);

  /* Row 1: minified through a mip chain of 32, 16, ... 1 texels, each level its own
   * colour scheme, with the mipmap filters. */
  glBindTexture(GL_TEXTURE_1D, tex[1]);
  for (i = 0; i <= 5; ++i) {
    GLubyte level[32 * 3];
    const int w = 32 >> i;
    int k;
    for (k = 0; k < w; ++k) {
      level[3 * k] = (GLubyte)(i * 50), level[3 * k + 1] = (GLubyte)(k * 255 / (w > 1 ? w - 1 : 1));
      level[3 * k + 2] = (GLubyte)(k % 2 ? 255 : 0);
    }
    glTexImage1D(GL_TEXTURE_1D, i, GL_RGB, w, 0, GL_RGB, GL_UNSIGNED_BYTE, level);
  }
  {
    static const GLenum mins[4] = {GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR,
                                   GL_LINEAR_MIPMAP_LINEAR};
    for (i = 0; i < 4; ++i) {
      glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, (GLint)mins[i]);
      quad(2.0f + 38 * (float)i, 64, 38.0f + 38 * (float)i, 80, 0, 6.5f + 3.0f * (float)i);
    }
  }
  glGetTexLevelParameteriv(GL_TEXTURE_1D, 3, GL_TEXTURE_WIDTH, &iv);
  conf_value("level3_width", iv);
  glGetTexLevelParameteriv(GL_TEXTURE_1D, 3, GL_TEXTURE_HEIGHT, &iv);
  conf_value("level3_height", iv);

  /* Row 2: a luminance texture replaced in part by glTexSubImage1D, through the
   * texture matrix, modulating smooth colours; in a display list. */
  glBindTexture(GL_TEXTURE_1D, tex[2]);
  {
    GLubyte lum[20];
    GLubyte sub[5] = {255, 0, 255, 0, 255};
    for (i = 0; i < 20; ++i) lum[i] = (GLubyte)(i * 12);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_LUMINANCE, 20, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
    glTexSubImage1D(GL_TEXTURE_1D, 0, 11, 5, GL_LUMINANCE, GL_UNSIGNED_BYTE, sub);
  }
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.1f, 0.3f, 0);
  glScalef(0.8f, 2, 1);
  glMatrixMode(GL_MODELVIEW);
  {
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0.5f, 0.2f);
    glTexCoord2f(0, 0);
    glVertex2f(4, 84);
    glColor3f(0.2f, 1, 0.5f);
    glTexCoord2f(1, 9);
    glVertex2f(76, 86);
    glColor3f(0.5f, 0.3f, 1);
    glTexCoord2f(0.5f, -4);
    glVertex2f(40, 124);
    glEnd();
    glEndList();
    glCallList(list);
    glDeleteLists(list, 1);
  }
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glColor3f(1, 1, 1);

  /* GL_TEXTURE_2D takes precedence: a 2-D texture enabled too draws instead. */
  {
    static const GLubyte checker[4 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255};
    glBindTexture(GL_TEXTURE_2D, tex[0] + 100);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    quad(84, 84, 116, 124, 0, 1);
    glDisable(GL_TEXTURE_2D);
  }

  /* A copy of framebuffer row 40 (row 0's quads) into a 1-D texture, drawn; a part
   * copied again from row 70. */
  glBindTexture(GL_TEXTURE_1D, tex[0]);
  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 40, 64, 0);
  glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 8, 10, 70, 16);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  quad(120, 84, 158, 124, 0, 1);
  glGetTexLevelParameteriv(GL_TEXTURE_1D, 0, GL_TEXTURE_WIDTH, &iv);
  conf_value("copied_width", iv);
  {
    GLubyte back[64 * 4];
    glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    conf_value("copied_texel5_r", back[5 * 4]);
    conf_value("copied_texel12_g", back[12 * 4 + 1]);
    conf_value("copied_texel40_b", back[40 * 4 + 2]);
  }
  conf_frame("textured1d");

  /* State and errors. */
  glPushAttrib(GL_ENABLE_BIT | GL_TEXTURE_BIT);
  glDisable(GL_TEXTURE_1D);
  glBindTexture(GL_TEXTURE_1D, 0);
  glPopAttrib();
  conf_value("popped_enabled", glIsEnabled(GL_TEXTURE_1D));
  glGetIntegerv(GL_TEXTURE_BINDING_1D, &iv);
  conf_value("popped_binding", iv == (GLint)tex[0]);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  conf_value("bind_1d_as_2d", glGetError());
  glBindTexture(GL_TEXTURE_1D, tex[0] + 100);
  conf_value("bind_2d_as_1d", glGetError());
  glTexImage1D(GL_TEXTURE_2D, 0, GL_RGB, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, ramp);
  conf_value("image_bad_target", glGetError());
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, -1, 0, GL_RGB, GL_UNSIGNED_BYTE, ramp);
  conf_value("image_negative", glGetError());
  glTexImage1D(GL_TEXTURE_1D, -1, GL_RGB, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, ramp);
  conf_value("image_bad_level", glGetError());
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 4, 0, GL_RGB, GL_RGBA, ramp);
  conf_value("image_bad_type", glGetError());
  glTexSubImage1D(GL_TEXTURE_1D, 0, 60, 8, GL_RGB, GL_UNSIGNED_BYTE, ramp);
  conf_value("sub_past_end", glGetError());
  glTexSubImage1D(GL_TEXTURE_1D, 9, 0, 1, GL_RGB, GL_UNSIGNED_BYTE, ramp);
  conf_value("sub_undefined_level", glGetError());
  glCopyTexImage1D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 4, 0);
  conf_value("copy_bad_target", glGetError());
  glCopyTexSubImage1D(GL_TEXTURE_1D, 0, -1, 0, 0, 4);
  conf_value("copy_sub_negative", glGetError());
  glCopyTexImage1D(GL_TEXTURE_1D, 0, 3, 0, 0, 4, 0); /* 1-4 are glTexImage's formats only */
  conf_value("copy_format_3", glGetError());
  glCopyTexImage2D(GL_TEXTURE_2D, 0, 4, 0, 0, 4, 4, 0);
  conf_value("copy_2d_format_4", glGetError());
  glDeleteTextures(3, tex);
  glGetIntegerv(GL_TEXTURE_BINDING_1D, &iv);
  conf_value("deleted_binding", iv);
  return conf_end();
}
