/* GL 1.3's multitexture: two texture units, each with its own texture, environment,
 * enable, texture matrix and glTexGen, applied in order. A light-mapped quad (a
 * checkered base modulated by a smooth light map on unit 1), a detail texture added on
 * unit 1, unit 0 off with unit 1 on, the coordinates from glMultiTexCoord, from each
 * unit's array (glClientActiveTexture), from glTexGen and through each unit's texture
 * matrix, in display lists; the queries, attribute groups and errors. */
#include "harness.h"

static void error(const char* name) { conf_value(name, glGetError()); }

static GLuint base_texture(void) {
  static GLubyte texels[8 * 8 * 3];
  GLuint t;
  int x, y;
  for (y = 0; y < 8; ++y)
    for (x = 0; x < 8; ++x) {
      GLubyte* p = texels + 3 * (y * 8 + x);
      const int on = (x + y) & 1;
      p[0] = on ? 220 : 60, p[1] = on ? 180 : 110, p[2] = on ? 90 : 200;
    }
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

/* A light map: bright in one corner, dark in the opposite, as luminance. */
static GLuint light_map(void) {
  static GLubyte texels[16 * 16];
  GLuint t;
  int x, y;
  for (y = 0; y < 16; ++y)
    for (x = 0; x < 16; ++x) texels[y * 16 + x] = (GLubyte)(255 - (x + y) * 7);
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 16, 16, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

/* A quad with unit 0's coordinates 0..2 (the base repeats) and unit 1's 0..1. */
static void quad(float x0, float y0, float x1, float y1) {
  glBegin(GL_QUADS);
  glMultiTexCoord2f(GL_TEXTURE0, 0, 0);
  glMultiTexCoord2f(GL_TEXTURE1, 0, 0);
  glVertex2f(x0, y0);
  glMultiTexCoord2f(GL_TEXTURE0, 2, 0);
  glMultiTexCoord2f(GL_TEXTURE1, 1, 0);
  glVertex2f(x1, y0);
  glMultiTexCoord2f(GL_TEXTURE0, 2, 2);
  glMultiTexCoord2f(GL_TEXTURE1, 1, 1);
  glVertex2f(x1, y1);
  glTexCoord2f(0, 2); /* glTexCoord is unit 0's */
  glMultiTexCoord2fv(GL_TEXTURE1, (const GLfloat[]){0, 1});
  glVertex2f(x0, y1);
  glEnd();
}

int main(int argc, char** argv) {
  static const GLfloat pos[8] = {0, 0, 1, 0, 1, 1, 0, 1};
  static const GLfloat tc0[8] = {0, 0, 3, 0, 3, 3, 0, 3};
  static const GLshort tc1[8] = {0, 0, 1, 0, 1, 1, 0, 1};
  static const GLfloat plane_s[4] = {0.02f, 0, 0, 0}, plane_t[4] = {0, 0.02f, 0, 0};
  GLuint base, light, list;
  GLint i = -1;
  GLfloat f[4] = {0, 0, 0, 0};
  GLvoid* p = NULL;
  conf_init(argc, argv, 160, 160);
  conf_ortho();
  base = base_texture();
  light = light_map();

  glGetIntegerv(GL_MAX_TEXTURE_UNITS, &i);
  conf_value("max_units_at_least_2", i >= 2);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &i);
  conf_value("initial_active", i);
  glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &i);
  conf_value("initial_client_active", i);

  /* Unit 0: the base, modulating white; unit 1: the light map, modulating. */
  glClearColor(0.2f, 0.2f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, base);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, light);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor3f(1, 1, 1);
  quad(6, 86, 70, 150); /* light-mapped (4 pixels a texel: edges between pixel centres) */
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
  glColor3f(0.6f, 0.6f, 0.6f);
  quad(86, 86, 150, 150); /* the map added */
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_TEXTURE_2D); /* unit 1 alone */
  glColor3f(0.9f, 0.5f, 0.2f);
  quad(6, 6, 70, 70);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glActiveTexture(GL_TEXTURE1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
  {
    static const GLfloat env[4] = {1, 0.2f, 0.2f, 1};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
  }
  quad(86, 6, 150, 70); /* base replaced, then blended towards red by the map */
  conf_frame("units");
  glGetIntegerv(GL_ACTIVE_TEXTURE, &i);
  conf_value("active_after", i);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &i);
  conf_value("unit1_binding_is_light", i == (GLint)light);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, f);
  conf_value("unit1_current_t", f[1]);
  glActiveTexture(GL_TEXTURE0);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, f);
  conf_value("unit0_current_t", f[1]);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &i);
  conf_value("unit0_binding_is_base", i == (GLint)base);
  conf_value("unit0_enabled", glIsEnabled(GL_TEXTURE_2D));
  error("units_error");

  /* Arrays per unit (glClientActiveTexture), each unit's texture matrix, glTexGen on
   * unit 1, in a display list. */
  glClear(GL_COLOR_BUFFER_BIT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glActiveTexture(GL_TEXTURE1);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glTranslatef(6, 6, 0);
  glScalef(72, 72, 1); /* (unit 0: 3 repeats of 8 texels, 3 pixels a texel) */
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glEnableClientState(GL_VERTEX_ARRAY);
  glClientActiveTexture(GL_TEXTURE0);
  glTexCoordPointer(2, GL_FLOAT, 0, tc0);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glClientActiveTexture(GL_TEXTURE1);
  glTexCoordPointer(2, GL_SHORT, 0, tc1);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glGetIntegerv(GL_TEXTURE_COORD_ARRAY_TYPE, &i);
  conf_value("unit1_array_type", i);
  glGetPointerv(GL_TEXTURE_COORD_ARRAY_POINTER, &p);
  conf_value("unit1_array_pointer", p == (GLvoid*)tc1);
  glDrawArrays(GL_QUADS, 0, 4);
  /* unit 1's matrix turns its map around; unit 0's stays the identity */
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.5f, 0.5f, 0);
  glRotatef(180, 0, 0, 1);
  glTranslatef(-0.5f, -0.5f, 0);
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(1.0f, 0, 0);
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glDrawArrays(GL_QUADS, 0, 4);
  glEndList();
  glCallList(list);
  glClientActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_COORD_ARRAY_TYPE, &i);
  conf_value("unit0_array_type", i);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glClientActiveTexture(GL_TEXTURE1);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glPopMatrix();
  /* glTexGen on unit 1 (object linear from the window position), immediate mode and
   * compiled glActiveTexture / glMultiTexCoord. */
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane_s);
  glTexGenfv(GL_T, GL_OBJECT_PLANE, plane_t);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glNewList(list, GL_COMPILE);
  glActiveTexture(GL_TEXTURE0);
  glBegin(GL_TRIANGLES);
  glMultiTexCoord2f(GL_TEXTURE0, 0, 0);
  glVertex2f(10, 86);
  glMultiTexCoord2f(GL_TEXTURE0, 2, 0);
  glVertex2f(138, 86);
  glMultiTexCoord2f(GL_TEXTURE0, 1, 2);
  glVertex2f(74, 150);
  glEnd();
  glEndList();
  glCallList(list);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &i);
  conf_value("active_after_list", i);
  glActiveTexture(GL_TEXTURE1);
  conf_value("unit1_gen_s", glIsEnabled(GL_TEXTURE_GEN_S));
  glActiveTexture(GL_TEXTURE0);
  conf_value("unit0_gen_s", glIsEnabled(GL_TEXTURE_GEN_S));
  glDeleteLists(list, 1);
  conf_frame("arrays_matrices_texgen");
  error("arrays_error");

  /* Attribute groups: GL_TEXTURE_BIT keeps every unit and the active one;
   * GL_ENABLE_BIT every unit's enables; the client stack the client unit and arrays. */
  glActiveTexture(GL_TEXTURE1);
  glPushAttrib(GL_TEXTURE_BIT | GL_ENABLE_BIT);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_TEXTURE_GEN_S);
  glBindTexture(GL_TEXTURE_2D, base);
  glActiveTexture(GL_TEXTURE0);
  glDisable(GL_TEXTURE_2D);
  glPopAttrib();
  glGetIntegerv(GL_ACTIVE_TEXTURE, &i);
  conf_value("popped_active", i);
  conf_value("popped_unit1_enabled", glIsEnabled(GL_TEXTURE_2D));
  conf_value("popped_unit1_gen_s", glIsEnabled(GL_TEXTURE_GEN_S));
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &i);
  conf_value("popped_unit1_binding_is_light", i == (GLint)light);
  glActiveTexture(GL_TEXTURE0);
  conf_value("popped_unit0_enabled", glIsEnabled(GL_TEXTURE_2D));
  glClientActiveTexture(GL_TEXTURE1);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glClientActiveTexture(GL_TEXTURE0);
  glTexCoordPointer(3, GL_DOUBLE, 0, NULL);
  glPopClientAttrib();
  glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &i);
  conf_value("popped_client_active", i);
  glClientActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_COORD_ARRAY_SIZE, &i);
  conf_value("popped_unit0_array_size", i);
  error("attrib_error");

  /* Errors: a unit past the last (of any implementation: Mesa's llvmpipe has dozens),
   * inside glBegin/glEnd. */
  glActiveTexture(GL_TEXTURE0 + 4096);
  error("active_texture_bad");
  glClientActiveTexture(GL_TEXTURE0 + 4096);
  error("client_active_texture_bad");
  glActiveTexture(GL_TEXTURE_2D);
  error("active_texture_not_a_unit");
  glBegin(GL_POINTS);
  glMultiTexCoord2f(GL_TEXTURE1, 1, 1); /* allowed */
  glEnd();
  error("multi_tex_coord_in_begin");
  glBegin(GL_POINTS);
  glActiveTexture(GL_TEXTURE1);
  glEnd();
  error("active_texture_in_begin");
  glGetIntegerv(GL_ACTIVE_TEXTURE, &i);
  conf_value("active_unchanged", i);
  glDeleteTextures(1, &base);
  glDeleteTextures(1, &light);
  return conf_end();
}
