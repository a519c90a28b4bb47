/* Sized internal formats (GL 1.1's table: GL_RGB4 ... GL_RGBA16, GL_ALPHA4 ...
 * GL_INTENSITY16, the luminance-alpha pairs, GL_R3_G3_B2) and GL 1.3's generic
 * compressed ones, in glTexImage2D, glTexImage1D, glTexImage3D and glCopyTexImage2D,
 * drawn with GL_REPLACE and GL_MODULATE; texel data of every type: the signed and
 * unsigned integer types, the twelve packed types of GL 1.2 (with byte swapping). The
 * images use 0 and full intensity where a format keeps few bits (Mesa keeps them at
 * their sizes, pGL at 8 bits: the spec lets each choose). Values: which components
 * glGetTexLevelParameteriv says have bits (zero or not: the counts are the
 * implementation's), the base format's components in glGetTexImage, GL_PROXY_TEXTURE_2D
 * of a sized format, the errors (a packed type of another number of components; the
 * 2-D copies to another target, a sub-image without pixels past the end). */
#include "harness.h"

static const GLenum formats[] = {
    GL_ALPHA4, GL_ALPHA12, GL_ALPHA16, GL_LUMINANCE4, GL_LUMINANCE12, GL_LUMINANCE16, GL_LUMINANCE4_ALPHA4,
    GL_LUMINANCE6_ALPHA2, GL_LUMINANCE12_ALPHA4, GL_LUMINANCE12_ALPHA12, GL_LUMINANCE16_ALPHA16, GL_INTENSITY4,
    GL_INTENSITY12, GL_INTENSITY16, GL_R3_G3_B2, GL_RGB4, GL_RGB5, GL_RGB10, GL_RGB12, GL_RGB16, GL_RGBA2, GL_RGBA4,
    GL_RGB5_A1, GL_RGB10_A2, GL_RGBA12, GL_RGBA16, GL_COMPRESSED_ALPHA, GL_COMPRESSED_LUMINANCE,
    GL_COMPRESSED_LUMINANCE_ALPHA, GL_COMPRESSED_INTENSITY, GL_COMPRESSED_RGB, GL_COMPRESSED_RGBA};
#define NFORMATS (int)(sizeof formats / sizeof formats[0])

static void quad(float x, float y, float w, float h) {
  glBegin(GL_QUADS);
  glTexCoord3f(0, 0, 0.5f);
  glVertex2f(x, y);
  glTexCoord3f(1, 0, 0.5f);
  glVertex2f(x + w, y);
  glTexCoord3f(1, 1, 0.5f);
  glVertex2f(x + w, y + h);
  glTexCoord3f(0, 1, 0.5f);
  glVertex2f(x, y + h);
  glEnd();
}

int main(int argc, char** argv) {
  /* 4x4 RGBA, each channel 0 or 255 in a different pattern (asymmetric). */
  GLubyte full[4 * 4 * 4];
  GLuint tex;
  GLint iv = 0;
  int i, k;
  char name[64];
  conf_init(argc, argv, 216, 160);
  conf_ortho();
  glClearColor(0.2f, 0.3f, 0.4f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  for (i = 0; i < 16; ++i) {
    full[4 * i] = (GLubyte)(i % 3 ? 255 : 0), full[4 * i + 1] = (GLubyte)(i % 5 < 2 ? 255 : 0);
    full[4 * i + 2] = (GLubyte)(i / 4 % 2 ? 255 : 0), full[4 * i + 3] = (GLubyte)(i % 2 ? 255 : 0);
  }
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

  /* Rows 0-1: every format, replace then modulate (a colour), blended by its alpha. */
  for (i = 0; i < NFORMATS; ++i) {
    GLint red = 0, green = 0, blue = 0, alpha = 0, lum = 0, inten = 0, depth = -1, compressed = -1;
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)formats[i], 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, full);
    snprintf(name, sizeof name, "image_error_%04x", formats[i]);
    conf_value(name, glGetError());
    /* (Mesa compresses GL_COMPRESSED_RGB and _RGBA, lossily: not drawn or read back.) */
    const int lossy = formats[i] == GL_COMPRESSED_RGB || formats[i] == GL_COMPRESSED_RGBA;
    /* Quads of 3 pixels a texel: no pixel centre on a texel's edge. */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glColor4f(1, 1, 1, 1);
    if (!lossy) quad(2.0f + 13 * (float)(i % 16), 2.0f + 26 * (float)(i / 16), 12, 12);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(0.9f, 0.5f, 1, 0.8f);
    if (!lossy) quad(2.0f + 13 * (float)(i % 16), 15.0f + 26 * (float)(i / 16), 12, 12);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &red);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_GREEN_SIZE, &green);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_BLUE_SIZE, &blue);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_ALPHA_SIZE, &alpha);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE, &lum);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTENSITY_SIZE, &inten);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &depth);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &compressed);
    /* Which components have bits, one digit each: r g b a l i d. */
    snprintf(name, sizeof name, "channels_%04x", formats[i]);
    conf_value(name, (red > 0) * 1000000 + (green > 0) * 100000 + (blue > 0) * 10000 + (alpha > 0) * 1000 +
                         (lum > 0) * 100 + (inten > 0) * 10 + (depth != 0));
    if (formats[i] < GL_COMPRESSED_ALPHA) { /* (Mesa may compress the generic ones) */
      snprintf(name, sizeof name, "compressed_%04x", formats[i]);
      conf_value(name, compressed);
    }
    if (!lossy) {
      GLubyte back[4 * 4 * 4];
      glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
      snprintf(name, sizeof name, "back_%04x", formats[i]);
      conf_value(name, back[5 * 4] + 2 * back[6 * 4 + 1] + 4 * back[7 * 4 + 2] + 8 * back[9 * 4 + 3]);
    }
  }
  glDisable(GL_BLEND);

  /* Row 2: the twelve packed types and BGRA, into RGBA16 and RGB5_A1, bytes swapped
   * in every other one; the integer types into GL_LUMINANCE12_ALPHA12. */
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glColor4f(1, 1, 1, 1);
  {
    static const GLenum types[12] = {GL_UNSIGNED_BYTE_3_3_2,        GL_UNSIGNED_BYTE_2_3_3_REV,
                                     GL_UNSIGNED_SHORT_5_6_5,       GL_UNSIGNED_SHORT_5_6_5_REV,
                                     GL_UNSIGNED_SHORT_4_4_4_4,     GL_UNSIGNED_SHORT_4_4_4_4_REV,
                                     GL_UNSIGNED_SHORT_5_5_5_1,     GL_UNSIGNED_SHORT_1_5_5_5_REV,
                                     GL_UNSIGNED_INT_8_8_8_8,       GL_UNSIGNED_INT_8_8_8_8_REV,
                                     GL_UNSIGNED_INT_10_10_10_2,    GL_UNSIGNED_INT_2_10_10_10_REV};
    GLuint words[16];
    for (i = 0; i < 16; ++i) words[i] = 0xf0c8a503u * (GLuint)(i + 1) ^ 0x5a5a0ff0u;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (k = 0; k < 12; ++k) {
      const GLenum format = k < 4 ? GL_RGB : (k % 3 ? GL_RGBA : GL_BGRA);
      glPixelStorei(GL_UNPACK_SWAP_BYTES, k % 2);
      glTexImage2D(GL_TEXTURE_2D, 0, k < 4 ? GL_RGB16 : (k % 2 ? GL_RGBA16 : GL_RGBA12), 4, 4, 0, format, types[k], words);
      snprintf(name, sizeof name, "packed_error_%d", k);
      conf_value(name, glGetError());
      quad(2.0f + 14 * (float)k, 56, 12, 12);
      {
        GLubyte back[4 * 4 * 4];
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
        /* The most significant bits only: 8 of them agree however the format is kept. */
        snprintf(name, sizeof name, "packed_back_%d", k);
        conf_value(name, (back[3 * 4] >> 5) * 64 + (back[10 * 4 + 1] >> 5) * 8 + (back[13 * 4 + 2] >> 5));
      }
    }
    glPixelStorei(GL_UNPACK_SWAP_BYTES, 0);
  }
  {
    static const GLenum types[6] = {GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_INT, GL_UNSIGNED_BYTE};
    static const GLubyte bytes[4 * 4 * 2 * 4] = {0x7f, 0xff, 0x00, 0x80, 0x40, 0x20, 0xff, 0x7f, 0x10, 0xf0, 0x33, 0xcc,
                                                0x00, 0x00, 0xff, 0xff, 0x7f, 0x7f, 0x80, 0x80, 0x01, 0xfe, 0x55, 0xaa};
    for (k = 0; k < 6; ++k) {
      glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE12_ALPHA12, 2, 2, 0, GL_LUMINANCE_ALPHA, types[k], bytes);
      quad(174.0f + 20 * (float)(k % 2), 56.0f + 14 * (float)(k / 2), 14, 14);
    }
  }

  /* Row 3: 1-D and 3-D images of sized formats; glCopyTexImage2D into sized formats. */
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_1D);
  glBindTexture(GL_TEXTURE_1D, tex + 1);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB10_A2, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, full);
  quad(2, 86, 48, 14);
  glDisable(GL_TEXTURE_1D);
  glEnable(GL_TEXTURE_3D);
  glBindTexture(GL_TEXTURE_3D, tex + 2);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_INTENSITY16, 2, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, full);
  quad(54, 86, 20, 16);
  glDisable(GL_TEXTURE_3D);
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, tex);
  {
    static const GLenum copies[4] = {GL_RGB5, GL_LUMINANCE16_ALPHA16, GL_RGBA4, GL_COMPRESSED_LUMINANCE};
    for (k = 0; k < 4; ++k) {
      glCopyTexImage2D(GL_TEXTURE_2D, 0, copies[k], 2 + 12 * k, 2, 8, 20, 0);
      snprintf(name, sizeof name, "copy_error_%d", k);
      conf_value(name, glGetError());
      quad(78.0f + 20 * (float)k, 86, 16, 40);
    }
  }
  conf_frame("formats");

  /* A proxy of a sized format; errors. */
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA12, 64, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &iv);
  conf_value("proxy_width", iv);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, full);
  conf_value("packed_565_rgba", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16, 4, 4, 0, GL_RGB, GL_UNSIGNED_INT_8_8_8_8, full);
  conf_value("packed_8888_rgb", glGetError());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, full);
  conf_value("sub_packed_4444_rgb", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, 0x8049 + 100, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, full);
  conf_value("bad_internal", glGetError());
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA2 + 100, 0, 0, 4, 4, 0);
  conf_value("copy_bad_internal", glGetError());
  /* (Not formats: the targets of the 2-D copies, the ranges of a sub-image without pixels.) */
  glCopyTexImage2D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, 4, 4, 0);
  conf_value("copy2d_on_1d", glGetError());
  glCopyTexSubImage2D(GL_TEXTURE_1D, 0, 0, 0, 0, 0, 4, 1);
  conf_value("copy_sub2d_on_1d", glGetError());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, full);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  conf_value("sub_null_past_end", glGetError());
  glDeleteTextures(1, &tex);
  return conf_end();
}
