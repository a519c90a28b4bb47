/* The level of detail's controls: GL 1.2's GL_TEXTURE_MIN_LOD and GL_TEXTURE_MAX_LOD,
 * GL 1.4's GL_TEXTURE_LOD_BIAS (the texture object's and the texture unit's,
 * glTexEnv(GL_TEXTURE_FILTER_CONTROL)), each with a 32 x 32 texture whose six levels are
 * six colours, drawn at exact scales (level of detail -1, 0, 1, 2 and 3) with the
 * mip-mapped filters; magnification chosen by a clamp; GL_MAX_TEXTURE_LOD_BIAS; errors. */
#include "harness.h"

static const GLubyte colours[6][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 0, 255}, {0, 255, 255}, {255, 255, 0}};

static void error(const char* name) { conf_value(name, glGetError()); }

/* A square of `size` pixels at (x, y) showing the whole texture. */
static void square(float x, float y, float size) {
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(x, y);
  glTexCoord2f(1, 0);
  glVertex2f(x + size, y);
  glTexCoord2f(1, 1);
  glVertex2f(x + size, y + size);
  glTexCoord2f(0, 1);
  glVertex2f(x, y + size);
  glEnd();
}

/* A row of the five scales (64, 32, 16, 8, 4 pixels: level of detail -1 to 3). */
static void scales(float y) {
  square(2, y, 64);
  square(70, y, 32);
  square(106, y, 16);
  square(126, y, 8);
  square(138, y, 4);
}

int main(int argc, char** argv) {
  static GLubyte texels[32 * 32 * 3];
  GLuint tex;
  GLfloat f = -1;
  int level, size, i;
  conf_init(argc, argv, 160, 200);
  conf_ortho();
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  for (level = 0, size = 32; size > 0; ++level, size /= 2) {
    for (i = 0; i < size * size; ++i) memcpy(texels + 3 * i, colours[level], 3);
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGB, size, size, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glEnable(GL_TEXTURE_2D);
  glGetFloatv(GL_MAX_TEXTURE_LOD_BIAS, &f);
  conf_value("max_bias_at_least_4", f >= 4);

  glClearColor(0.5f, 0.5f, 0.5f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  scales(2); /* no controls */
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 1.5f);
  scales(70); /* every scale at 1.5 or more: blended levels 1 and 2 */
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -1000);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 1.25f);
  scales(138); /* at most 1.25 */
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 1000);
  conf_frame("clamp_linear");

  /* Between levels with the nearest-level filters, and a clamp above 0 making the
   * magnified squares minified. */
  glClear(GL_COLOR_BUFFER_BIT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 2.25f);
  scales(2);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 0.75f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 2.75f);
  scales(70);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 0.5f);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 3.5f);
  scales(138);
  conf_frame("clamp_nearest");

  /* The bias: the object's, the unit's, both (their sum), and a negative one that
   * magnifies. */
  glClear(GL_COLOR_BUFFER_BIT);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, -1000);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 1000);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.5f);
  scales(2);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.5f);
  scales(50);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.0f);
  scales(98);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -1.25f);
  scales(136);
  /* The bias before the clamp. */
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 0.5f);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 2);
  square(120, 160, 32);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 1000);
  conf_frame("bias");
  error("draw_error");

  /* Errors: the filter control's only parameter is the bias. */
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  error("filter_control_bad_pname");
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS, 1);
  error("env_lod_bias");
  glBegin(GL_POINTS);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 1);
  glEnd();
  error("in_begin");
  glDeleteTextures(1, &tex);
  return conf_end();
}
