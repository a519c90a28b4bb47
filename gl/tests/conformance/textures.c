/* Textures: RGB, RGBA, LUMINANCE and ALPHA images of odd sizes, glTexSubImage2D, every
 * filter (the four mip-map ones with gluBuild2DMipmaps and GL_GENERATE_MIPMAP), wrap
 * modes REPEAT, CLAMP, CLAMP_TO_EDGE, environments MODULATE, REPLACE, DECAL, BLEND, ADD;
 * the sized and intensity internal formats. */
#include "harness.h"

static unsigned char checker[64 * 64 * 4];

static void make_checker(int size, int square) {
  int x, y;
  for (y = 0; y < size; ++y)
    for (x = 0; x < size; ++x) {
      unsigned char* p = checker + 4 * (y * size + x);
      const int on = ((x / square) + (y / square)) % 2;
      p[0] = on ? 230 : 40, p[1] = on ? 200 : (unsigned char)(60 + 2 * x), p[2] = on ? 80 : 160;
      p[3] = (unsigned char)(on ? 255 : 90 + y);
    }
}

static void textured_quad(float x0, float y0, float x1, float y1, float s1, float t1) {
  glBegin(GL_QUADS);
  glTexCoord2f(-s1 * 0.25f, -t1 * 0.25f);
  glVertex2f(x0, y0);
  glTexCoord2f(s1, -t1 * 0.25f);
  glVertex2f(x1, y0);
  glTexCoord2f(s1, t1);
  glVertex2f(x1, y1);
  glTexCoord2f(-s1 * 0.25f, t1);
  glVertex2f(x0, y1);
  glEnd();
}

/* A floor going into the distance, for minification. */
static void floor_quad(void) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex3f(-2, -1, -1.5f);
  glTexCoord2f(3, 0);
  glVertex3f(2, -1, -1.5f);
  glTexCoord2f(3, 6);
  glVertex3f(2, -1, -30);
  glTexCoord2f(0, 6);
  glVertex3f(-2, -1, -30);
  glEnd();
}

int main(int argc, char** argv) {
  GLuint tex[4];
  int i;
  conf_init(argc, argv, 192, 128);
  make_checker(64, 8);
  glGenTextures(4, tex);

  /* tex[0]: RGBA 64x64 with mip-maps from GLU. */
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 64, 64, GL_RGBA, GL_UNSIGNED_BYTE, checker);
  /* tex[1]: RGB 13x7 (any size), rows byte aligned. */
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  {
    unsigned char rgb[13 * 7 * 3];
    for (i = 0; i < 13 * 7; ++i) rgb[3 * i] = (unsigned char)(i * 37), rgb[3 * i + 1] = (unsigned char)(i * 11), rgb[3 * i + 2] = (unsigned char)(255 - i * 3);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 13, 7, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  /* tex[2]: LUMINANCE 16x16 with GL_GENERATE_MIPMAP, then a sub-image. */
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  {
    unsigned char lum[16 * 16], patch[4 * 4];
    for (i = 0; i < 256; ++i) lum[i] = (unsigned char)(((i % 16) ^ (i / 16)) * 16);
    for (i = 0; i < 16; ++i) patch[i] = 255;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 16, 16, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 6, 6, 4, 4, GL_LUMINANCE, GL_UNSIGNED_BYTE, patch);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  /* tex[3]: ALPHA 8x8. */
  glBindTexture(GL_TEXTURE_2D, tex[3]);
  {
    unsigned char a[64];
    for (i = 0; i < 64; ++i) a[i] = (unsigned char)((i % 8) * 32 + (i / 8) * 3);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, 8, 8, 0, GL_ALPHA, GL_UNSIGNED_BYTE, a);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);

  glEnable(GL_TEXTURE_2D);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, 192, 0, 128);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  /* Frame 1: wrap modes and magnification filters on tex[0] and tex[1]. */
  glClearColor(0.3f, 0.3f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  for (i = 0; i < 3; ++i) {
    static const GLenum wraps[3] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE};
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wraps[i]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wraps[(i + 1) % 3]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, i == 1 ? GL_NEAREST : GL_LINEAR);
    textured_quad(4.0f + 62 * i, 4, 62.0f + 62 * i, 62, 1.6f, 1.6f);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, tex[1]);
  textured_quad(4, 66, 90, 124, 1, 1);
  glBindTexture(GL_TEXTURE_2D, tex[2]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  textured_quad(100, 66, 188, 124, 1, 1);
  /* The texture matrix: a rotated and scaled checker on a small quad at the top. */
  glMatrixMode(GL_TEXTURE);
  glPushMatrix();
  glTranslatef(0.5f, 0.5f, 0);
  glRotatef(30, 0, 0, 1);
  glScalef(2, 1.5f, 1);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glMatrixMode(GL_MODELVIEW);
  textured_quad(150, 2, 190, 30, 1, 1);
  glMatrixMode(GL_TEXTURE);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
  conf_frame("wrap_mag");

  /* Frame 2: environments on a coloured quad. */
  glClear(GL_COLOR_BUFFER_BIT);
  {
    static const GLenum envs[4] = {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND};
    const GLfloat env_color[4] = {0.1f, 0.9f, 0.2f, 0.5f};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_color);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (i = 0; i < 16; ++i) {
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, envs[i % 4]);
      glBindTexture(GL_TEXTURE_2D, tex[i / 4]);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, i / 4 == 2 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
      glBegin(GL_QUADS);
      glColor4f(1, 0.5f, 0.2f, 0.8f);
      glTexCoord2f(0, 0);
      glVertex2f(4.0f + 47 * (i % 4), 4.0f + 31 * (i / 4));
      glColor4f(0.2f, 0.6f, 1, 1);
      glTexCoord2f(1, 0);
      glVertex2f(48.0f + 47 * (i % 4), 4.0f + 31 * (i / 4));
      glTexCoord2f(1, 1);
      glVertex2f(48.0f + 47 * (i % 4), 32.0f + 31 * (i / 4));
      glColor4f(1, 1, 1, 0.6f);
      glTexCoord2f(0, 1);
      glVertex2f(4.0f + 47 * (i % 4), 32.0f + 31 * (i / 4));
      glEnd();
    }
    glDisable(GL_BLEND);
  }
  conf_frame("env");

  /* Frames 3-4: minification with each filter on a receding floor. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(60, 192.0 / 128.0, 0.5, 50);
  glMatrixMode(GL_MODELVIEW);
  /* Modulated by grey: where a nearest filter's texel choice is a tie (a pixel centre
   * on a texel edge, to within float rounding) the two renderers may pick either. */
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor3f(0.55f, 0.55f, 0.55f);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  for (i = 0; i < 6; ++i) {
    static const GLenum mins[6] = {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                                   GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
    char name[32];
    glClear(GL_COLOR_BUFFER_BIT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mins[i]);
    floor_quad();
    snprintf(name, sizeof name, "min%d", i);
    conf_frame(name);
  }

  /* Frame 5: the sized and intensity internal formats (gl.h's names) from one RGBA
   * image, each under MODULATE and ADD, with GL_DITHER on (no effect at 8 bits); 3
   * pixels a texel, so no nearest-texel ties. Then one pixel read back as GL_RED,
   * GL_GREEN, GL_BLUE. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluOrtho2D(0, 192, 0, 128);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_DITHER);
  glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
  conf_value("clear_stencil_accum_bits_error", glGetError());
  make_checker(8, 2);
  glBindTexture(GL_TEXTURE_2D, tex[0]);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glColor4f(0.6f, 0.3f, 0.9f, 0.7f);
  for (i = 0; i < 14; ++i) {
    static const GLenum formats[7] = {GL_RGB8, GL_RGBA8, GL_ALPHA8, GL_LUMINANCE8, GL_LUMINANCE8_ALPHA8,
                                      GL_INTENSITY, GL_INTENSITY8};
    const float x = 4.0f + 27 * (i % 7), y = 20.0f + 50 * (i / 7);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)formats[i % 7], 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, i < 7 ? GL_MODULATE : GL_ADD);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(x, y);
    glTexCoord2f(1, 0);
    glVertex2f(x + 24, y);
    glTexCoord2f(1, 1);
    glVertex2f(x + 24, y + 24);
    glTexCoord2f(0, 1);
    glVertex2f(x, y + 24);
    glEnd();
  }
  conf_value("sized_formats_error", glGetError());
  conf_frame("sized");
  {
    static const GLenum channels[3] = {GL_RED, GL_GREEN, GL_BLUE};
    for (i = 0; i < 3; ++i) {
      GLubyte v = 0;
      glReadPixels(5, 21, 1, 1, channels[i], GL_UNSIGNED_BYTE, &v);
      conf_value("sized_pixel_channel", v);
    }
  }
  glDeleteTextures(4, tex);

  /* glCopyTexImage2D and glCopyTexSubImage2D from the colour buffer (rectangles inside
   * it), drawn back magnified; glGetTexLevelParameteriv of the copy. */
  {
    static const GLenum pnames[6] = {GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_BORDER, GL_TEXTURE_RED_SIZE,
                                     GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE};
    GLuint copy;
    GLint v;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_TEXTURE_2D);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0), glVertex2f(-1, -1);
    glColor3f(0, 1, 0), glVertex2f(-0.5f, -1);
    glColor3f(0, 0, 1), glVertex2f(-0.75f, -0.5f);
    glEnd();
    glGenTextures(1, &copy);
    glBindTexture(GL_TEXTURE_2D, copy);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, 32, 32, 0);
    conf_value("copy_error", glGetError());
    for (i = 0; i < 6; ++i) {
      glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, pnames[i], &v);
      conf_value("copy_level_parameter", v);
    }
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 8, 8, 4, 2, 16, 8);
    conf_value("copy_sub_error", glGetError());
    {
      /* glGetTexImage of the copy: RGBA bytes, and LUMINANCE floats (its red). */
      static GLubyte texels[32 * 32 * 4];
      static GLfloat lum[32 * 32];
      unsigned long sum = 0;
      int k;
      glPixelStorei(GL_PACK_ALIGNMENT, 1);
      glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
      for (k = 0; k < 32 * 32 * 4; ++k) sum = (sum * 31 + texels[k]) % 1000003;
      conf_value("get_tex_image_sum", (double)sum);
      glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_FLOAT, lum);
      conf_value("get_tex_image_lum", (double)lum[3 * 32 + 5]);
      glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, 0x9999, texels);
      conf_value("get_tex_image_bad_type", glGetError());
      glPixelStorei(GL_PACK_ALIGNMENT, 4);
    }
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 20, 20, 0, 0, 16, 16); /* beyond the texture */
    conf_value("copy_sub_outside", glGetError());
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    textured_quad(-0.2f, -0.9f, 0.9f, 0.9f, 1, 1);
    glDisable(GL_TEXTURE_2D);
    conf_frame("copy");
    glDeleteTextures(1, &copy);
  }

  /* GL 1.2's GL_TEXTURE_BASE_LEVEL and GL_TEXTURE_MAX_LEVEL: six levels of solid,
   * distinct colours; quads at 32, 8 and 2 pixels with the base level 0, 2 and 1 and
   * the max level 1 and 3. */
  {
    static const GLubyte level_colours[6][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}, {0, 255, 255},
                                                {255, 0, 255}};
    static GLubyte solid[32 * 32 * 3];
    GLuint levels_tex;
    int lv, k, row;
    glGenTextures(1, &levels_tex);
    glBindTexture(GL_TEXTURE_2D, levels_tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (lv = 0; lv < 6; ++lv) {
      const int size = 32 >> lv;
      for (k = 0; k < size * size; ++k) memcpy(solid + 3 * k, level_colours[lv], 3);
      glTexImage2D(GL_TEXTURE_2D, lv, GL_RGB, size, size, 0, GL_RGB, GL_UNSIGNED_BYTE, solid);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 192, 0, 128, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    for (row = 0; row < 3; ++row) {
      static const int base[3] = {0, 2, 1}, max[3] = {1000, 3, 1};
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, base[row]);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, max[row]);
      for (k = 0; k < 3; ++k) {
        const float size = (float)(32 >> (2 * k)), x = 4.0f + 60.0f * k, y = 4.0f + 40.0f * row;
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0), glVertex2f(x, y);
        glTexCoord2f(1, 0), glVertex2f(x + size, y);
        glTexCoord2f(1, 1), glVertex2f(x + size, y + size);
        glTexCoord2f(0, 1), glVertex2f(x, y + size);
        glEnd();
      }
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1);
    conf_value("base_level_negative", glGetError());
    glDisable(GL_TEXTURE_2D);
    conf_frame("levels");
    glDeleteTextures(1, &levels_tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  }
  return conf_end();
}
