/* 3-D textures (GL 1.2): glTexImage3D of an 8x4x6 RGBA image read through
 * GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES, a row length and skipped rows, drawn
 * slice by slice with GL_NEAREST and projective coordinates (q != 1); magnified with
 * GL_LINEAR across r under GL_REPEAT, GL_CLAMP_TO_EDGE and GL_MIRRORED_REPEAT; a mip
 * chain of 16^3 down to 1 given by hand, minified with the four mipmap filters; r from
 * glTexCoord3f through the texture matrix and from glTexGen's R; glTexSubImage3D and
 * glCopyTexSubImage3D; GL_TEXTURE_3D taking precedence over GL_TEXTURE_2D; an RGB and
 * a luminance-alpha texture; in a display list. Values: glGetTexImage with
 * GL_PACK_IMAGE_HEIGHT and GL_PACK_SKIP_IMAGES, glGetTexLevelParameteriv (the depth),
 * GL_PROXY_TEXTURE_3D, GL_TEXTURE_BINDING_3D, glIsEnabled, glPushAttrib, the errors.
 * Compared with Mesa. */
#include "harness.h"

/* A w x h quad at (x, y) whose texture coordinates run (s0, t0) -> (s1, t1) with r from
 * r0 (left) to r1 (right), all times q. */
static void quad3(float x, float y, float w, float h, float s0, float s1, float t0, float t1, float r0, float r1,
                  float q) {
  glBegin(GL_QUADS);
  glTexCoord4f(s0 * q, t0 * q, r0 * q, q);
  glVertex2f(x, y);
  glTexCoord4f(s1 * q, t0 * q, r1 * q, q);
  glVertex2f(x + w, y);
  glTexCoord4f(s1 * q, t1 * q, r1 * q, q);
  glVertex2f(x + w, y + h);
  glTexCoord4f(s0 * q, t1 * q, r0 * q, q);
  glVertex2f(x, y + h);
  glEnd();
}

static GLubyte texel(int x, int y, int z, int c) { return (GLubyte)((x * 37 + y * 71 + z * 53 + c * 97 + x * y * z) % 256); }

int main(int argc, char** argv) {
  GLuint tex[4];
  GLint iv = 0;
  int i, x, y, z;
  conf_init(argc, argv, 192, 160);
  conf_ortho();
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glGenTextures(4, tex);
  glBindTexture(GL_TEXTURE_3D, tex[0]);
  glGetIntegerv(GL_TEXTURE_BINDING_3D, &iv);
  conf_value("binding_3d", iv == (GLint)tex[0]);
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &iv);
  conf_value("max_3d_at_least_256", iv >= 256);

  /* An 8x4x6 image inside client memory of 10-texel rows, 5-row images, one image and
   * one row skipped: only the texels GL_UNPACK_* name are read. */
  {
    static GLubyte client[7 * 5 * 10 * 4];
    for (z = 0; z < 7; ++z)
      for (y = 0; y < 5; ++y)
        for (x = 0; x < 10; ++x)
          for (i = 0; i < 4; ++i) client[((z * 5 + y) * 10 + x) * 4 + i] = (GLubyte)(i == 3 ? 255 : 17);
    for (z = 0; z < 6; ++z)
      for (y = 0; y < 4; ++y)
        for (x = 0; x < 8; ++x)
          for (i = 0; i < 4; ++i) client[(((z + 1) * 5 + y + 1) * 10 + x) * 4 + i] = texel(x, y, z, i);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 10);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 5);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 8, 4, 6, 0, GL_RGBA, GL_UNSIGNED_BYTE, client);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  }
  conf_value("image_error", glGetError());
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_3D);
  conf_value("enabled_3d", glIsEnabled(GL_TEXTURE_3D));
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

  /* Row 0: the six slices, nearest, r at each slice's centre, q = 1 and q = 1.7. */
  for (z = 0; z < 6; ++z) {
    const float r = ((float)z + 0.5f) / 6.0f;
    quad3(2.0f + 16 * (float)z, 2, 16, 16, 0, 1, 0, 1, r, r, 1.0f);
    quad3(98.0f + 16 * (float)z, 2, 16, 16, 0, 1, 0, 1, r, r, 1.7f);
  }

  /* Row 1: magnified with GL_LINEAR, r running across the quad past both ends, under
   * the three wrap modes of r. */
  {
    static const GLenum wraps[3] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT};
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (i = 0; i < 3; ++i) {
      glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, (GLint)wraps[i]);
      quad3(2.0f + 62 * (float)i, 22, 60, 24, 0.2f, 0.8f, 0.1f, 0.9f, -0.7f, 1.6f, 1.0f);
    }
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_REPEAT);
  }

  /* Row 2: a mip chain 16^3 ... 1, each level its own colours, minified. */
  glBindTexture(GL_TEXTURE_3D, tex[1]);
  {
    static GLubyte level[16 * 16 * 16 * 3];
    for (i = 0; i <= 4; ++i) {
      const int n = 16 >> i;
      for (z = 0; z < n; ++z)
        for (y = 0; y < n; ++y)
          for (x = 0; x < n; ++x) {
            GLubyte* p = level + ((z * n + y) * n + x) * 3;
            p[0] = (GLubyte)(i * 60), p[1] = (GLubyte)((x + y) % 2 ? 220 : 30), p[2] = (GLubyte)(z * 255 / (n > 1 ? n - 1 : 1));
          }
      glTexImage3D(GL_TEXTURE_3D, i, GL_RGB, n, n, n, 0, GL_RGB, GL_UNSIGNED_BYTE, level);
    }
  }
  {
    static const GLenum mins[4] = {GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR,
                                   GL_LINEAR_MIPMAP_LINEAR};
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (i = 0; i < 4; ++i) {
      glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, (GLint)mins[i]);
      /* (s and t end off the texel grid: a texel edge exactly at a pixel centre is a tie
       * that FMA and non-FMA SIMD targets may round either way.) */
      quad3(2.0f + 46 * (float)i, 50, 44, 20, 0, 5.1f + 2.0f * (float)i, 0, 1.53f, 0.1f, 3.0f + (float)i, 1.0f);
    }
  }
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 2, GL_TEXTURE_DEPTH, &iv);
  conf_value("level2_depth", iv);
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 2, GL_TEXTURE_WIDTH, &iv);
  conf_value("level2_width", iv);

  /* Row 3: an RGB texture modulating smooth colours, r from glTexCoord3f through the
   * texture matrix, and from glTexGen's R (object linear), in a display list. */
  glBindTexture(GL_TEXTURE_3D, tex[2]);
  {
    GLubyte rgb[4 * 4 * 4 * 3];
    for (z = 0; z < 4; ++z)
      for (y = 0; y < 4; ++y)
        for (x = 0; x < 4; ++x)
          for (i = 0; i < 3; ++i) rgb[((z * 4 + y) * 4 + x) * 3 + i] = (GLubyte)(i == z % 3 ? 240 : (x + y) * 30);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 4, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  }
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.1f, 0, 0.3f);
  glScalef(1, 1, 0.6f);
  glMatrixMode(GL_MODELVIEW);
  {
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0.6f, 0.3f);
    glTexCoord3f(0, 0, 0);
    glVertex2f(4, 76);
    glColor3f(0.3f, 1, 0.6f);
    glTexCoord3f(1, 0.2f, 1.5f);
    glVertex2f(70, 78);
    glColor3f(0.6f, 0.4f, 1);
    glTexCoord3f(0.4f, 1, -0.5f);
    glVertex2f(36, 118);
    glEnd();
    glEndList();
    glCallList(list);
    glDeleteLists(list, 1);
  }
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glColor3f(1, 1, 1);
  {
    static const GLfloat plane_r[4] = {0.02f, 0.005f, 0, -0.5f};
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_R, GL_OBJECT_PLANE, plane_r);
    glEnable(GL_TEXTURE_GEN_R);
    quad3(74, 76, 44, 42, 0, 1, 0, 1, 0, 0, 1.0f);
    glDisable(GL_TEXTURE_GEN_R);
  }

  /* GL_TEXTURE_3D takes precedence: with a 2-D texture enabled too, the 3-D one draws. */
  {
    static const GLubyte checker[4 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255};
    glBindTexture(GL_TEXTURE_2D, tex[3]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    quad3(122, 76, 30, 20, 0, 1, 0, 1, 0.2f, 0.9f, 1.0f);
    glDisable(GL_TEXTURE_3D);
    quad3(156, 76, 30, 20, 0, 1, 0, 1, 0.2f, 0.9f, 1.0f);
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_3D);
  }

  /* Row 4: slices replaced by glTexSubImage3D (a luminance-alpha 2x2x2 block) and by
   * glCopyTexSubImage3D (row 1 of the frame into slice 3), drawn nearest. */
  glBindTexture(GL_TEXTURE_3D, tex[0]);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  {
    static const GLubyte la[2 * 2 * 2 * 2] = {255, 255, 0, 128, 60, 255, 200, 40, 0, 255, 255, 0, 128, 128, 30, 200};
    glTexSubImage3D(GL_TEXTURE_3D, 0, 5, 1, 2, 2, 2, 2, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
  }
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 1, 0, 3, 30, 30, 6, 4);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  for (z = 0; z < 6; ++z) {
    const float r = ((float)z + 0.5f) / 6.0f;
    quad3(2.0f + 24 * (float)z, 124, 24, 32, 0, 1, 0, 1, r, r, 1.0f);
  }
  {
    GLubyte back[9 * 5 * 9 * 4];
    memset(back, 0, sizeof back);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_IMAGE_HEIGHT, 5);
    glPixelStorei(GL_PACK_SKIP_IMAGES, 2);
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    glPixelStorei(GL_PACK_IMAGE_HEIGHT, 0);
    glPixelStorei(GL_PACK_SKIP_IMAGES, 0);
    /* texel (x, y, z) at ((z + 2) * 5 + y) * 8 + x */
    conf_value("back_skipped", back[0] + back[5 * 8 * 4 * 2 - 1]);
    conf_value("back_x3y2z0_r", back[((2 * 5 + 2) * 8 + 3) * 4]);
    conf_value("back_x5y1z2_g", back[((4 * 5 + 1) * 8 + 5) * 4 + 1]);
    conf_value("back_x6y2z3_a", back[((5 * 5 + 2) * 8 + 6) * 4 + 3]);
    conf_value("back_x2y1z3_b", back[((5 * 5 + 1) * 8 + 2) * 4 + 2]);
    conf_value("back_x7y3z5_b", back[((7 * 5 + 3) * 8 + 7) * 4 + 2]);
  }
  conf_frame("textured3d");

  /* Proxies: a size that fits, one that does not. */
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 64, 32, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &iv);
  conf_value("proxy_fits_depth", iv);
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 64, 32, 65536, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &iv);
  conf_value("proxy_too_deep_width", iv);
  conf_value("proxy_error", glGetError());

  /* State and errors. */
  glPushAttrib(GL_ENABLE_BIT | GL_TEXTURE_BIT);
  glDisable(GL_TEXTURE_3D);
  glBindTexture(GL_TEXTURE_3D, 0);
  glPopAttrib();
  conf_value("popped_enabled", glIsEnabled(GL_TEXTURE_3D));
  glGetIntegerv(GL_TEXTURE_BINDING_3D, &iv);
  conf_value("popped_binding", iv == (GLint)tex[0]);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  conf_value("bind_3d_as_2d", glGetError());
  glBindTexture(GL_TEXTURE_3D, tex[3]);
  conf_value("bind_2d_as_3d", glGetError());
  glTexImage3D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  conf_value("image_bad_target", glGetError());
  glTexImage2D(GL_TEXTURE_3D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  conf_value("image2d_on_3d", glGetError());
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 4, 4, -1, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  conf_value("image_negative_depth", glGetError());
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 4, 4, 4, 2, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  conf_value("image_border_2", glGetError());
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 4, 4, 4, 0, GL_RGB, GL_RGBA, NULL);
  conf_value("image_bad_type", glGetError());
  glTexImage3D(GL_TEXTURE_3D, 0, 17, 4, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  conf_value("image_bad_internal", glGetError());
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 5, 2, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  conf_value("sub_past_end", glGetError());
  glTexSubImage3D(GL_TEXTURE_3D, 9, 0, 0, 0, 1, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  conf_value("sub_undefined_level", glGetError());
  glTexSubImage3D(GL_TEXTURE_1D, 0, 0, 0, 0, 1, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, NULL);
  conf_value("sub_bad_target", glGetError());
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 6, 0, 0, 2, 2);
  conf_value("copy_sub_past_depth", glGetError());
  glCopyTexSubImage3D(GL_PROXY_TEXTURE_3D, 0, 0, 0, 0, 0, 0, 2, 2);
  conf_value("copy_sub_proxy", glGetError());
  glCopyTexImage2D(GL_TEXTURE_3D, 0, GL_RGB, 0, 0, 4, 4, 0);
  conf_value("copy2d_on_3d", glGetError());
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_LINEAR);
  conf_value("wrap_r_bad", glGetError());
  glDeleteTextures(4, tex);
  glGetIntegerv(GL_TEXTURE_BINDING_3D, &iv);
  conf_value("deleted_binding", iv);
  return conf_end();
}
