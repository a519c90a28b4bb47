/* GL 1.4's colour sum and fog coordinates, GL 1.2's separate specular colour: the
 * secondary colour added after the texture environment (glSecondaryColor3*, GL_COLOR_SUM),
 * smooth and flat; lit spheres with GL_SEPARATE_SPECULAR_COLOR against GL_SINGLE_COLOR on
 * a texture, two-sided; glFogCoord with GL_FOG_COORD_SRC; the secondary colour and fog
 * coordinate arrays (glDrawArrays, glArrayElement in a display list); their queries,
 * attribute groups and errors. */
#define GL_GLEXT_PROTOTYPES 1 /* GL 1.4's functions in the system headers */
#include "harness.h"

static void error(const char* name) { conf_value(name, glGetError()); }

static void checker_texture(void) {
  static GLubyte texels[8 * 8 * 3];
  int x, y;
  for (y = 0; y < 8; ++y)
    for (x = 0; x < 8; ++x) {
      GLubyte* t = texels + 3 * (y * 8 + x);
      const int on = (x + y) & 1;
      t[0] = on ? 230 : 40, t[1] = on ? 200 : 90, t[2] = on ? 60 : 160;
    }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

/* A quad with a secondary colour per corner (and texture coordinates). */
static void quad(float x0, float y0, float x1, float y1, const float sec[4][3]) {
  glBegin(GL_QUADS);
  glColor3f(0.8f, 0.3f, 0.2f);
  glSecondaryColor3fv(sec[0]);
  glTexCoord2f(0, 0);
  glVertex2f(x0, y0);
  glColor3f(0.2f, 0.7f, 0.3f);
  glSecondaryColor3fv(sec[1]);
  glTexCoord2f(1, 0);
  glVertex2f(x1, y0);
  glColor3f(0.3f, 0.3f, 0.9f);
  glSecondaryColor3fv(sec[2]);
  glTexCoord2f(1, 1);
  glVertex2f(x1, y1);
  glColor3f(0.9f, 0.9f, 0.1f);
  glSecondaryColor3fv(sec[3]);
  glTexCoord2f(0, 1);
  glVertex2f(x0, y1);
  glEnd();
}

static void lit_spheres(GLUquadric* q) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-2.2, 2.2, -1.1, 1.1, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(-1.1f, 0, 0);
  glRotatef(70, 1, 0.3f, 0);
  gluSphere(q, 1.0, 24, 16);
  glLoadIdentity();
  glTranslatef(1.1f, 0, 0);
  glRotatef(70, 1, 0.3f, 0);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  gluSphere(q, 1.0, 24, 16);
}

int main(int argc, char** argv) {
  static const float sec_a[4][3] = {{0.5f, 0, 0}, {0, 0.5f, 0}, {0, 0, 0.5f}, {0.4f, 0.4f, 0.4f}};
  static const float sec_b[4][3] = {{0.1f, 0.6f, 0.9f}, {0.9f, 0.1f, 0}, {0, 0, 0}, {0.3f, 0, 0.7f}};
  static const GLfloat light_pos[4] = {-1, 1.5f, 2, 0};
  static const GLfloat white[4] = {1, 1, 1, 1}, spec[4] = {0.9f, 0.8f, 0.7f, 1}, diffuse[4] = {0.9f, 0.9f, 0.9f, 1};
  static const GLfloat back_diffuse[4] = {0.2f, 0.5f, 0.9f, 1};
  /* Arrays: x, y; r, g, b (secondary, unsigned bytes); a fog coordinate. */
  static const GLfloat pos[8] = {10, 110, 70, 110, 70, 150, 10, 150};
  static const GLubyte sec_ub[12] = {255, 0, 0, 0, 128, 0, 0, 0, 255, 64, 64, 64};
  static const GLfloat fog[4] = {0, 0.3f, 1, 0.6f};
  GLuint tex, list;
  GLfloat f[4] = {0, 0, 0, 0};
  GLint i = -1;
  GLvoid* p = NULL;
  GLUquadric* q;
  conf_init(argc, argv, 160, 160);
  conf_ortho();
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  checker_texture();

  /* The initial state. */
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, f);
  conf_value("initial_secondary_r", f[0]);
  conf_value("initial_secondary_a", f[3]);
  conf_value("initial_color_sum", glIsEnabled(GL_COLOR_SUM));
  glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &i);
  conf_value("initial_color_control", i);
  glGetIntegerv(GL_FOG_COORD_SRC, &i);
  conf_value("initial_fog_coord_src", i);
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_SIZE, &i);
  conf_value("initial_secondary_array_size", i);
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_TYPE, &i);
  conf_value("initial_secondary_array_type", i);
  glGetIntegerv(GL_FOG_COORD_ARRAY_TYPE, &i);
  conf_value("initial_fog_coord_array_type", i);

  /* The secondary colour: after the texture (modulate), smooth and flat; none without
   * GL_COLOR_SUM. */
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_COLOR_SUM);
  /* (72 pixels: the texel edges fall between pixel centres) */
  quad(5, 5, 77, 77, sec_a);
  glEnable(GL_TEXTURE_2D);
  quad(83, 5, 155, 77, sec_a);
  glShadeModel(GL_FLAT);
  quad(83, 83, 155, 155, sec_b);
  glShadeModel(GL_SMOOTH);
  glDisable(GL_COLOR_SUM);
  quad(5, 83, 77, 155, sec_b);
  glEnable(GL_COLOR_SUM);
  /* Alpha is not summed; blending sees the primary alpha. */
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_TEXTURE_2D);
  glColor4f(0.2f, 0.2f, 0.8f, 0.5f);
  glSecondaryColor3f(0.6f, 0.5f, 0);
  glRectf(40, 40, 120, 120);
  glDisable(GL_BLEND);
  conf_frame("secondary");
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, f);
  conf_value("current_secondary_g", f[1]);
  glSecondaryColor3ub(255, 128, 0);
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, f);
  conf_value("secondary_ub_g", f[1]);
  glSecondaryColor3s(32767, -32768, 0);
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, f);
  conf_value("secondary_s_r", f[0]);
  conf_value("secondary_s_g", f[1]);
  error("secondary_error");

  /* Separate specular: the highlight stays white on the texture (left); a single colour
   * modulates it (right). Two-sided lighting with the back faces showing through a cut. */
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_COLOR_SUM);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glMaterialfv(GL_BACK, GL_DIFFUSE, back_diffuse);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &i);
  conf_value("color_control_separate", i);
  q = gluNewQuadric();
  gluQuadricTexture(q, GL_TRUE);
  lit_spheres(q);
  conf_frame("separate_specular");

  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
  glEnable(GL_CLIP_PLANE0);
  {
    static const GLdouble cut[4] = {0, 0, -1, 0.3};
    glClipPlane(GL_CLIP_PLANE0, cut);
  }
  glShadeModel(GL_FLAT);
  lit_spheres(q);
  glShadeModel(GL_SMOOTH);
  glDisable(GL_CLIP_PLANE0);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  conf_frame("separate_two_sided_flat");
  gluDeleteQuadric(q);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_TEXTURE_2D);
  conf_ortho();

  /* Fog coordinates: linear fog from glFogCoord; then the eye's depth again. */
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0);
  glFogf(GL_FOG_END, 1);
  {
    static const GLfloat fog_color[4] = {0.9f, 0.9f, 0.2f, 1};
    glFogfv(GL_FOG_COLOR, fog_color);
  }
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
  glBegin(GL_TRIANGLE_STRIP);
  glColor3f(0.1f, 0.2f, 0.9f);
  glFogCoordf(0);
  glVertex2f(5, 5);
  glFogCoordf(0.2f);
  glVertex2f(5, 45);
  glFogCoordf(0.6f);
  glVertex2f(155, 5);
  glFogCoordf(1);
  glVertex2f(155, 45);
  glEnd();
  glGetFloatv(GL_CURRENT_FOG_COORD, f);
  conf_value("current_fog_coord", f[0]);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glRectf(5, 50, 155, 60); /* eye depth 0: no fog */
  glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);

  /* The arrays: secondary colours (unsigned bytes) and fog coordinates, drawn, then
   * compiled element by element into a display list and called. */
  glEnable(GL_COLOR_SUM);
  glColor3f(0.1f, 0.1f, 0.3f);
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, sec_ub);
  glFogCoordPointer(GL_FLOAT, 0, fog);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
  glEnableClientState(GL_FOG_COORD_ARRAY);
  conf_value("secondary_array_enabled", glIsEnabled(GL_SECONDARY_COLOR_ARRAY));
  conf_value("fog_coord_array_enabled", glIsEnabled(GL_FOG_COORD_ARRAY));
  glDrawArrays(GL_QUADS, 0, 4);
  glGetPointerv(GL_SECONDARY_COLOR_ARRAY_POINTER, &p);
  conf_value("secondary_pointer", p == (GLvoid*)sec_ub);
  glGetPointerv(GL_FOG_COORD_ARRAY_POINTER, &p);
  conf_value("fog_coord_pointer", p == (GLvoid*)fog);
  glGetFloatv(GL_CURRENT_FOG_COORD, f);
  conf_value("fog_coord_after_draw", f[0]);
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTranslatef(80, 0, 0);
  /* (triangles: Mesa's display lists split a quad along another diagonal than its
   * immediate mode does) */
  glBegin(GL_TRIANGLES);
  for (i = 0; i < 6; ++i) glArrayElement(i < 3 ? i : i == 3 ? 0 : i - 2);
  glEnd();
  glTranslatef(-80, 0, 0);
  glEndList();
  glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
  glDisableClientState(GL_FOG_COORD_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glSecondaryColor3f(0, 0, 0);
  glFogCoordf(0.5f);
  glCallList(list);
  /* glSecondaryColor and glFogCoord compiled into a list. */
  glNewList(list, GL_COMPILE);
  glSecondaryColor3f(0.7f, 0, 0.7f);
  glFogCoordf(0.25f);
  glEndList();
  glCallList(list);
  glColor3f(0.2f, 0.2f, 0.2f);
  glRectf(5, 120, 155, 155);
  glDeleteLists(list, 1);
  glDisable(GL_FOG);
  glDisable(GL_COLOR_SUM);
  conf_frame("fog_coord_arrays");

  /* Attribute groups: GL_CURRENT_BIT, GL_LIGHTING_BIT (the colour control). GL 1.5's
   * table 6.11 puts GL_COLOR_SUM in GL_FOG_BIT and GL_ENABLE_BIT and GL_FOG_COORD_SRC in
   * GL_FOG_BIT, which pGL restores and Mesa does not (not compared). */
  glSecondaryColor3f(0.25f, 0.5f, 0.75f);
  glFogCoordf(2);
  glPushAttrib(GL_CURRENT_BIT | GL_LIGHTING_BIT);
  glSecondaryColor3f(1, 1, 1);
  glFogCoordf(3);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glPopAttrib();
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, f);
  conf_value("popped_secondary_b", f[2]);
  glGetFloatv(GL_CURRENT_FOG_COORD, f);
  conf_value("popped_fog_coord", f[0]);
  glGetIntegerv(GL_LIGHT_MODEL_COLOR_CONTROL, &i);
  conf_value("popped_color_control", i);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glSecondaryColorPointer(3, GL_SHORT, 6, NULL);
  glPopClientAttrib();
  glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_TYPE, &i);
  conf_value("client_popped_secondary_type", i);
  error("attrib_error");

  /* Errors. */
  /* (GL 1.5: the size is 3; Mesa takes 4 too, as later GLs do: size 2 is wrong in both) */
  glSecondaryColorPointer(2, GL_FLOAT, 0, sec_a);
  error("secondary_pointer_size_2");
  glSecondaryColorPointer(3, GL_FLOAT, -1, sec_a);
  error("secondary_pointer_negative_stride");
  glSecondaryColorPointer(3, GL_2_BYTES, 0, sec_a);
  error("secondary_pointer_bad_type");
  glFogCoordPointer(GL_INT, 0, fog);
  error("fog_coord_pointer_bad_type");
  glFogCoordPointer(GL_FLOAT, -4, fog);
  error("fog_coord_pointer_negative_stride");
  glFogi(GL_FOG_COORD_SRC, GL_FOG);
  error("fog_coord_src_bad");
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_FRONT);
  error("color_control_bad");
  glBegin(GL_POINTS);
  glSecondaryColor3f(1, 0, 0); /* allowed between glBegin and glEnd */
  glFogCoordf(1);
  glEnd();
  error("inside_begin");
  glBegin(GL_POINTS);
  glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
  glEnd();
  error("light_model_inside_begin");
  glDeleteTextures(1, &tex);
  return conf_end();
}
