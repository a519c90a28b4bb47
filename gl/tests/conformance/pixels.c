/* The raster position and pixel rectangles: glRasterPos (transformed, clipped, its
 * colour lit or not, texture coordinates, distance), glWindowPos, glBitmap (origins,
 * moves, bit order, row length, skips, alignment), glDrawPixels (formats, types, the
 * packed types, glPixelStore's unpack state, blending, the depth test, depth images),
 * glPixelZoom (enlarged, shrunk, mirrored), glCopyPixels (colour and depth), in
 * display lists; their errors and glGet values. */
#define GL_GLEXT_PROTOTYPES 1 /* glWindowPos in the system headers (GL 1.4) */
#include "harness.h"

#define W 120
#define H 80

/* A 12 x 9 bitmap, different in each row and column (rows bottom first, 2 bytes each,
 * most significant bit first). */
static const GLubyte glyph[9 * 2] = {0xFF, 0xF0, 0x80, 0x10, 0xC0, 0x30, 0xA0, 0x50, 0x90,
                                     0x90, 0x88, 0x00, 0x84, 0x00, 0xFE, 0x00, 0x81, 0xC0};

static void errors(const char* name) {
  conf_value(name, glGetError());
}

static void values(const char* name, GLenum pname, int n) {
  GLfloat v[4];
  char k[80];
  int i;
  glGetFloatv(pname, v);
  for (i = 0; i < n; ++i) {
    snprintf(k, sizeof k, "%s_%d", name, i);
    conf_value(k, v[i]);
  }
}

static void ortho(void) {
  glViewport(0, 0, W, H);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, W, 0, H);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* An asymmetric w x h RGBA8 image: red across, green up, blue on a checker. */
static void image(GLubyte* px, int w, int h) {
  int x, y;
  for (y = 0; y < h; ++y)
    for (x = 0; x < w; ++x) {
      GLubyte* p = px + 4 * (y * w + x);
      p[0] = (GLubyte)(x * 255 / (w - 1));
      p[1] = (GLubyte)(y * 255 / (h - 1));
      p[2] = (GLubyte)((x + y) % 3 == 0 ? 255 : 40);
      p[3] = (GLubyte)(128 + x * 8);
    }
}

static void bitmaps(void) {
  static GLubyte padded[9 * 4];
  int i;
  ortho();
  glClearColor(0.1f, 0.1f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  /* The colour is taken when the raster position is set. */
  glColor3f(1, 0.2f, 0.2f);
  glRasterPos2i(4, 4);
  glColor3f(0, 1, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (i = 0; i < 4; ++i) glBitmap(12, 9, (GLfloat)i, 0, 14, 2, glyph);
  values("bitmap_moved", GL_CURRENT_RASTER_POSITION, 4);
  /* A fractional position is floored; the origin is subtracted. */
  glRasterPos2f(10.7f, 30.5f);
  glBitmap(12, 9, -2.5f, 1, 0, 0, glyph);
  /* LSB first, a row length and skipped rows and pixels, alignment 4. */
  for (i = 0; i < 9; ++i) {
    padded[4 * i] = 0;
    padded[4 * i + 1] = glyph[2 * i];
    padded[4 * i + 2] = glyph[2 * i + 1];
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 8);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 30);
  glRasterPos2i(40, 30);
  glBitmap(12, 9, 0, 0, 0, 0, padded);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glColor3f(0.3f, 0.6f, 1);
  glRasterPos2i(60, 30);
  glBitmap(12, 6, 0, 0, 0, 0, padded);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  /* Partly outside the window on the left and top; an invalid position draws nothing
   * and does not move. */
  glColor3f(1, 1, 0);
  glRasterPos2i(2, 74);
  glBitmap(12, 9, 6, 0, 0, 0, glyph);
  glRasterPos2i(-5, 10);
  values("bitmap_invalid_valid", GL_CURRENT_RASTER_POSITION_VALID, 1);
  glBitmap(12, 9, 0, 0, 30, 0, glyph);
  values("bitmap_invalid_pos", GL_CURRENT_RASTER_POSITION, 2);
  /* In a display list, at a glWindowPos, with blending and the alpha of the colour. */
  glNewList(1, GL_COMPILE);
  glBitmap(12, 9, 0, 0, 13, 0, glyph);
  glBitmap(12, 9, 0, 0, 13, 0, glyph);
  glEndList();
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(1, 1, 1, 0.5f);
  glWindowPos2i(70, 60);
  glCallList(1);
  glDisable(GL_BLEND);
  /* A null bitmap only moves the position. */
  glWindowPos2i(90, 5);
  glBitmap(0, 0, 0, 0, 7, 8, NULL);
  values("bitmap_null_move", GL_CURRENT_RASTER_POSITION, 2);
  glBitmap(12, 9, 0, 0, 0, 0, glyph);
  conf_frame("bitmap");
}

static void draw_pixels(void) {
  static GLubyte rgba[13 * 7 * 4], rgb[13 * 7 * 3 + 64], lum[16 * 16 * 2]; /* LUMINANCE_ALPHA reads 2 a pixel */
  static GLushort s565[13 * 7], s4444[13 * 7], swapped[13 * 7 * 3];
  static GLuint u8888[13 * 7], u1010[13 * 7];
  static GLfloat f[13 * 7 * 4];
  int i;
  ortho();
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  image(rgba, 13, 7);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  /* RGBA, and RGB rows of 39 bytes padded to 40. */
  glRasterPos2i(2, 2);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  for (i = 0; i < 13 * 7; ++i) {
    int row = i / 13, col = i % 13;
    GLubyte* d = rgb + row * 40 + col * 3;
    d[0] = rgba[4 * i + 2], d[1] = rgba[4 * i], d[2] = rgba[4 * i + 1];
  }
  glRasterPos2i(18, 2);
  glDrawPixels(13, 7, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  glRasterPos2i(34, 2);
  glDrawPixels(13, 7, GL_BGR, GL_UNSIGNED_BYTE, rgb);
  /* Luminance, alpha-only with blending, red only, a row length and skips. */
  for (i = 0; i < 16 * 16 * 2; ++i) lum[i] = (GLubyte)((i % 16) * 16 + (i / 16) % 16);
  glRasterPos2i(50, 2);
  glDrawPixels(16, 16, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 16);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 5);
  glRasterPos2i(70, 2);
  glDrawPixels(9, 7, GL_RED, GL_UNSIGNED_BYTE, lum);
  glRasterPos2i(82, 2);
  glDrawPixels(9, 7, GL_GREEN, GL_UNSIGNED_BYTE, lum);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glRasterPos2i(94, 2);
  glDrawPixels(16, 16, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, lum);
  glRasterPos2i(2, 12);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glDisable(GL_BLEND);
  /* The packed types, byte-swapped shorts, floats. */
  for (i = 0; i < 13 * 7; ++i) {
    const GLubyte* p = rgba + 4 * i;
    s565[i] = (GLushort)((p[0] >> 3) << 11 | (p[1] >> 2) << 5 | p[2] >> 3);
    s4444[i] = (GLushort)((p[0] >> 4) | (p[1] >> 4) << 4 | (p[2] >> 4) << 8 | (p[3] >> 4) << 12);
    u8888[i] = (GLuint)p[0] << 24 | (GLuint)p[1] << 16 | (GLuint)p[2] << 8 | p[3];
    u1010[i] = (GLuint)(p[0] * 4) | (GLuint)(p[1] * 4) << 10 | (GLuint)(p[2] * 4) << 20 | 3u << 30;
    swapped[3 * i] = (GLushort)(p[1] << 8 | p[0]);
    swapped[3 * i + 1] = (GLushort)(p[2] << 8);
    swapped[3 * i + 2] = (GLushort)(0x80 << 8 | 0x7f);
    f[4 * i] = p[2] / 255.0f, f[4 * i + 1] = p[0] / 255.0f, f[4 * i + 2] = 1.5f, f[4 * i + 3] = 1;
  }
  /* Rows of 13 shorts (26 bytes) are packed: at the default alignment of 4 GL would
   * pad them to 28 and read past these arrays. */
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glRasterPos2i(18, 22);
  glDrawPixels(13, 7, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, s565);
  glRasterPos2i(34, 22);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV, s4444);
  glRasterPos2i(50, 22);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, u8888);
  glRasterPos2i(66, 22);
  glDrawPixels(13, 7, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8, u8888);
  glRasterPos2i(82, 22);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, u1010);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  glRasterPos2i(2, 32);
  glDrawPixels(13, 7, GL_RGB, GL_UNSIGNED_SHORT, swapped);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glRasterPos2i(18, 32);
  glDrawPixels(13, 7, GL_RGBA, GL_FLOAT, f);
  /* In a display list: the pixels are taken at glNewList time. */
  glNewList(2, GL_COMPILE);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glEndList();
  memset(rgba, 0, sizeof rgba);
  glRasterPos2i(34, 32);
  glCallList(2);
  /* Partly outside the window. */
  glRasterPos2i(110, 75);
  glCallList(2);
  conf_frame("drawpixels");
}

static void zoom(void) {
  static GLubyte rgba[13 * 7 * 4];
  ortho();
  glClear(GL_COLOR_BUFFER_BIT);
  image(rgba, 13, 7);
  glRasterPos2i(2, 2);
  glPixelZoom(2, 3);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glRasterPos2f(60.25f, 2);
  glPixelZoom(-1.2f, 1);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glRasterPos2i(64, 40);
  glPixelZoom(0.5f, -2);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glRasterPos2i(80, 30);
  glPixelZoom(3, 3);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  /* Shrunk and mirrored both ways, from fractional positions (rounded, as Mesa), by
   * zooms that put no fragment centre exactly on the edge between two zoomed pixels
   * (which GL leaves to the implementation). */
  glRasterPos2f(2.25f, 60.75f);
  glPixelZoom(0.6f, 0.6f);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glRasterPos2f(40.25f, 78.25f);
  glPixelZoom(1.2f, -1.8f);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  values("zoom", GL_ZOOM_X, 1);
  values("zoom_y", GL_ZOOM_Y, 1);
  glPixelZoom(1, 1);
  conf_frame("zoom");
}

static void depth_and_copy(void) {
  static GLubyte rgba[13 * 7 * 4];
  static GLfloat depth[20 * 10];
  int i;
  ortho();
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.2f, 0.2f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  /* A depth image in the raster colour, then a flat quad at depth 0.5 half behind it. */
  for (i = 0; i < 20 * 10; ++i) depth[i] = (float)(i % 20) / 19.0f;
  glColor3f(0, 0.5f, 1);
  glRasterPos3f(4, 4, 0);
  glDrawPixels(20, 10, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  glColor3f(1, 0.5f, 0);
  glBegin(GL_QUADS);
  glVertex3f(2, 2, 0);
  glVertex3f(30, 2, 0);
  glVertex3f(30, 16, 0);
  glVertex3f(2, 16, 0);
  glEnd();
  /* Colour pixels at the raster position's depth (z = 0.5 is window depth 0.25). */
  image(rgba, 13, 7);
  glRasterPos3f(40, 4, -0.5f);
  glDrawPixels(13, 7, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  glColor3f(1, 1, 1);
  glBegin(GL_QUADS);
  glVertex3f(45, 2, 0);
  glVertex3f(60, 2, 0);
  glVertex3f(60, 16, 0);
  glVertex3f(45, 16, 0);
  glEnd();
  glDisable(GL_DEPTH_TEST);
  /* Copies: colour, zoomed, overlapping, from outside the window, depth. */
  glRasterPos2i(4, 30);
  glCopyPixels(2, 2, 60, 15, GL_COLOR);
  glRasterPos2i(70, 4);
  glPixelZoom(2, 2);
  glCopyPixels(40, 4, 13, 7, GL_COLOR);
  glPixelZoom(1, 1);
  glRasterPos2i(10, 34);
  glCopyPixels(4, 30, 30, 10, GL_COLOR);
  glRasterPos2i(4, 55);
  glCopyPixels(-6, -4, 30, 20, GL_COLOR);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glColor3f(1, 0, 1);
  glRasterPos2i(70, 40);
  glCopyPixels(4, 4, 20, 10, GL_DEPTH);
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
  {
    GLfloat d[3];
    glReadPixels(75, 45, 3, 1, GL_DEPTH_COMPONENT, GL_FLOAT, d);
    for (i = 0; i < 3; ++i) {
      char k[32];
      snprintf(k, sizeof k, "copied_depth_%d", i);
      conf_value(k, d[i]);
    }
  }
  conf_frame("depth_copy");
}

/* glPixelStore's unpack state applies to textures too: a 5 x 4 texture taken out of a
 * 9-pixel-wide image (row length, skipped rows and pixels, alignment 2), and
 * gluBuild2DMipmaps under the same state. (Not byte-swapped floats: Mesa 22's
 * glTexImage2D reads them unswapped.) */
static void texture_unpack(void) {
  static GLubyte big[9 * 7 * 3 + 16];
  int i;
  for (i = 0; i < 9 * 7 * 3; ++i) big[i] = (GLubyte)(i * 37 % 251);
  ortho();
  glClear(GL_COLOR_BUFFER_BIT);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 9);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 5, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, big);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0), glVertex2i(4, 4);
  glTexCoord2f(1, 0), glVertex2i(54, 4);
  glTexCoord2f(1, 1), glVertex2i(54, 44);
  glTexCoord2f(0, 1), glVertex2i(4, 44);
  glEnd();
  gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 4, 4, GL_RGB, GL_UNSIGNED_BYTE, big);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0), glVertex2i(4, 50);
  glTexCoord2f(1, 0), glVertex2i(52, 50);
  glTexCoord2f(1, 1), glVertex2i(52, 78);
  glTexCoord2f(0, 1), glVertex2i(4, 78);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  values("glu_kept_row_length", GL_UNPACK_ROW_LENGTH, 1);
  values("glu_kept_alignment", GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  conf_frame("texture_unpack");
  /* glReadPixels under the pack state: row length, skips, byte-swapped floats. */
  {
    static GLubyte buf[7 * 4 * 3];
    GLfloat fl[4];
    char k[40];
    memset(buf, 0xAB, sizeof buf);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 7);
    glPixelStorei(GL_PACK_SKIP_ROWS, 1);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 2);
    glReadPixels(10, 10, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, buf);
    for (i = 0; i < 7 * 4 * 3; i += 5) {
      snprintf(k, sizeof k, "packed_%d", i);
      conf_value(k, buf[i]);
    }
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
    glReadPixels(70, 10, 1, 1, GL_RGBA, GL_FLOAT, fl);
    glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (i = 0; i < 4; ++i) {
      GLubyte* b = (GLubyte*)&fl[i];
      snprintf(k, sizeof k, "swapped_float_%d", i);
      conf_value(k, b[0] * 16777216.0 + b[1] * 65536.0 + b[2] * 256.0 + b[3]);
    }
  }
}

static void raster_state(void) {
  static const GLfloat pos[4] = {1, 2, 3, 0}, diffuse[4] = {0.8f, 0.4f, 0.2f, 1};
  ortho();
  /* Transformed: modelview, projection, viewport, depth range. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60, 1.5, 1, 20);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(0.5f, -0.25f, -5);
  glRotatef(30, 0, 1, 0);
  glDepthRange(0.2, 0.9);
  glColor4f(0.25f, 0.5f, 0.75f, 1);
  glTexCoord4f(0.5f, 0.25f, 2, 1);
  glMatrixMode(GL_TEXTURE);
  glScalef(2, 3, 1);
  glMatrixMode(GL_MODELVIEW);
  glRasterPos3f(0.3f, 0.2f, 0.4f);
  values("rp_position", GL_CURRENT_RASTER_POSITION, 4);
  values("rp_valid", GL_CURRENT_RASTER_POSITION_VALID, 1);
  values("rp_color", GL_CURRENT_RASTER_COLOR, 4);
  values("rp_texcoords", GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
  values("rp_distance", GL_CURRENT_RASTER_DISTANCE, 1);
  /* Lit. */
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
  glNormal3f(0, 0, 1);
  glRasterPos3f(0.3f, 0.2f, 0.4f);
  values("rp_lit_color", GL_CURRENT_RASTER_COLOR, 4);
  glDisable(GL_LIGHTING);
  /* Behind the far plane, beyond the left: invalid; the old values stay. */
  glRasterPos3f(0, 0, -30);
  values("rp_far_valid", GL_CURRENT_RASTER_POSITION_VALID, 1);
  glRasterPos3f(-10, 0, 0);
  values("rp_left_valid", GL_CURRENT_RASTER_POSITION_VALID, 1);
  values("rp_left_position", GL_CURRENT_RASTER_POSITION, 2);
  /* glWindowPos: valid, z through the depth range, colour and coordinates as they are. */
  glWindowPos3f(7.5f, -3, 0.5f);
  values("wp_valid", GL_CURRENT_RASTER_POSITION_VALID, 1);
  values("wp_position", GL_CURRENT_RASTER_POSITION, 4);
  values("wp_texcoords", GL_CURRENT_RASTER_TEXTURE_COORDS, 4);
  values("wp_distance", GL_CURRENT_RASTER_DISTANCE, 1);
  glWindowPos2s(3, 4);
  values("wp2_position", GL_CURRENT_RASTER_POSITION, 3);
  glDepthRange(0, 1);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  /* glPixelStore's values. */
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 17);
  glPixelStoref(GL_UNPACK_SKIP_ROWS, 2.6f);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 5);
  glPixelStorei(GL_UNPACK_LSB_FIRST, 3);
  values("unpack_row_length", GL_UNPACK_ROW_LENGTH, 1);
  values("unpack_skip_rows", GL_UNPACK_SKIP_ROWS, 1);
  values("pack_skip_pixels", GL_PACK_SKIP_PIXELS, 1);
  values("unpack_lsb_first", GL_UNPACK_LSB_FIRST, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_LSB_FIRST, 0);
  errors("state_errors");
}

static void misuse(void) {
  static GLubyte px[64];
  glRasterPos2i(1, 1);
  glBitmap(-1, 2, 0, 0, 0, 0, px);
  errors("bitmap_negative");
  glDrawPixels(2, -2, GL_RGBA, GL_UNSIGNED_BYTE, px);
  errors("drawpixels_negative");
  glDrawPixels(2, 2, GL_RGBA + 77, GL_UNSIGNED_BYTE, px);
  errors("drawpixels_bad_format");
  glDrawPixels(2, 2, GL_RGBA, GL_RGBA, px);
  errors("drawpixels_bad_type");
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, px);
  errors("drawpixels_packed_mismatch");
  glDrawPixels(2, 2, GL_RGB, GL_UNSIGNED_INT_8_8_8_8, px);
  errors("drawpixels_packed_mismatch4");
  glDrawPixels(2, 2, GL_RGBA, GL_BITMAP, px);
  errors("drawpixels_bitmap_rgba");
  glDrawPixels(2, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, px);
  errors("drawpixels_no_stencil");
  glCopyPixels(0, 0, 2, 2, GL_RGBA);
  errors("copypixels_bad_type");
  glCopyPixels(0, 0, -2, 2, GL_COLOR);
  errors("copypixels_negative");
  glCopyPixels(0, 0, 2, 2, GL_STENCIL);
  errors("copypixels_no_stencil");
  glPixelStorei(GL_UNPACK_ALIGNMENT, 3);
  errors("pixelstore_alignment");
  glPixelStorei(GL_UNPACK_ROW_LENGTH, -1);
  errors("pixelstore_negative");
  glPixelStorei(GL_RGBA, 1);
  errors("pixelstore_bad_name");
  glBegin(GL_POINTS);
  glRasterPos2i(1, 1);
  glGetError();
  glEnd();
  errors("rasterpos_in_begin");
  glBegin(GL_POINTS);
  glBitmap(1, 1, 0, 0, 0, 0, px);
  glEnd();
  errors("bitmap_in_begin");
  glBegin(GL_POINTS);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  glEnd();
  errors("drawpixels_in_begin");
  glBegin(GL_POINTS);
  glWindowPos2i(1, 1);
  glEnd();
  errors("windowpos_in_begin");
  glBegin(GL_POINTS);
  glPixelZoom(2, 2);
  glEnd();
  errors("pixelzoom_in_begin");
}

int main(int argc, char** argv) {
  conf_init(argc, argv, W, H);
  bitmaps();
  draw_pixels();
  zoom();
  depth_and_copy();
  texture_unpack();
  raster_state();
  misuse();
  return conf_end();
}
