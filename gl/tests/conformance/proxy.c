/* Proxy textures (GL_PROXY_TEXTURE_2D): an image that fits sets the proxy level's size
 * and format, one too large sets them to 0 without an error, and the errors of
 * glTexImage2D leave the proxy as it was; the proxy changes neither the bound texture
 * nor what is drawn, and is not compiled into display lists. */
#include "harness.h"

static void error(const char* name) { conf_value(name, glGetError()); }

static void level(const char* name, GLenum target, int lvl) {
  char n[64];
  GLint v = -1;
  glGetTexLevelParameteriv(target, lvl, GL_TEXTURE_WIDTH, &v);
  snprintf(n, sizeof n, "%s_width", name);
  conf_value(n, v);
  v = -1;
  glGetTexLevelParameteriv(target, lvl, GL_TEXTURE_HEIGHT, &v);
  snprintf(n, sizeof n, "%s_height", name);
  conf_value(n, v);
}

int main(int argc, char** argv) {
  static const GLubyte texel[4] = {0, 200, 40, 255};
  GLint max = 0;
  GLuint list;
  conf_init(argc, argv, 32, 32);
  conf_ortho();
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max);
  level("initial", GL_PROXY_TEXTURE_2D, 0);

  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 64, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  error("fits");
  level("fits", GL_PROXY_TEXTURE_2D, 0);
  level("bound_unchanged", GL_TEXTURE_2D, 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 2, GL_RGB, 8, 4, 0, GL_RGB, GL_FLOAT, NULL);
  level("level2", GL_PROXY_TEXTURE_2D, 2);
  level("level0_kept", GL_PROXY_TEXTURE_2D, 0);

  /* Errors leave the proxy as it was. */
  glTexImage2D(GL_PROXY_TEXTURE_2D, 5555, GL_RGBA, 8, 8, 0, GL_RGBA, GL_FLOAT, NULL);
  error("bad_level");
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, -8, 8, 0, GL_RGBA, GL_FLOAT, NULL);
  error("negative");
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, 8, 2, GL_RGBA, GL_FLOAT, NULL);
  error("bad_border");
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, NULL);
  error("packed_mismatch");
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, 12345, 8, 8, 0, GL_RGBA, GL_FLOAT, NULL);
  error("bad_internal");
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_RGBA, NULL);
  error("bad_type");
  level("after_errors", GL_PROXY_TEXTURE_2D, 0);

  /* Too large: zeroed, no error. */
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, max * 2, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  error("too_wide");
  level("too_wide", GL_PROXY_TEXTURE_2D, 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, max, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  {
    GLint w = -1;
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    conf_value("max_fits", w == max);
  }
  glTexImage2D(GL_PROXY_TEXTURE_2D, 1, GL_RGBA, max, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  error("too_wide_level1");
  level("too_wide_level1", GL_PROXY_TEXTURE_2D, 1);

  /* Not compiled: executed at once, the list left empty. */
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glEndList();
  level("in_list", GL_PROXY_TEXTURE_2D, 0);
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glCallList(list);
  level("list_called", GL_PROXY_TEXTURE_2D, 0);

  /* The bound texture still draws. */
  glEnable(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glRectf(4, 4, 28, 28);
  conf_frame("drawn");
  error("final");
  return conf_end();
}
