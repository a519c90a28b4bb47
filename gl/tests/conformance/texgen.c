/* Texture coordinate generation: glTexGen's object linear (planes given as floats,
 * doubles and ints), eye linear (planes taken through the modelview of their time),
 * sphere map, normal map and reflection map, each on its own coordinates with the
 * texture matrix after them, mixed with glTexCoord's (t given, s and q generated:
 * projective), in a display list and through vertex arrays; the raster position's
 * texture coordinates; glGetTexGen, glIsEnabled, glPushAttrib / glPopAttrib and the
 * errors. An asymmetric texture (red across, green up, blue falling) so that a swapped
 * or mirrored coordinate shows. */
#include <math.h>

#include "harness.h"

#define W 128
#define H 96

static void values4(const char* name, const GLfloat* v, int n) {
  char k[80];
  int i;
  for (i = 0; i < n; ++i) {
    snprintf(k, sizeof k, "%s_%d", name, i);
    conf_value(k, v[i]);
  }
}

static void gen_values(const char* name, GLenum coord, GLenum pname, int n) {
  GLfloat v[4] = {0, 0, 0, 0};
  glGetTexGenfv(coord, pname, v);
  values4(name, v, n);
}

static void texture(void) {
  static unsigned char texels[16 * 16 * 3];
  int i, j;
  for (j = 0; j < 16; ++j)
    for (i = 0; i < 16; ++i) {
      unsigned char* t = texels + 3 * (j * 16 + i);
      t[0] = (unsigned char)(i * 16), t[1] = (unsigned char)(j * 16), t[2] = (unsigned char)(255 - (i + j) * 7);
    }
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
}

/* A grid of triangles in z = 0 over [-1.5, 1.5] x [-1, 1], no texture coordinates given. */
static void grid(void) {
  int i, j;
  glBegin(GL_TRIANGLES);
  for (j = 0; j < 8; ++j)
    for (i = 0; i < 12; ++i) {
      float x = -1.5f + 0.25f * (float)i, y = -1 + 0.25f * (float)j;
      glVertex3f(x, y, 0), glVertex3f(x + 0.25f, y, 0), glVertex3f(x + 0.25f, y + 0.25f, 0);
      glVertex3f(x, y, 0), glVertex3f(x + 0.25f, y + 0.25f, 0), glVertex3f(x, y + 0.25f, 0);
    }
  glEnd();
}

/* A sphere of triangles with unit normals (the normal is the position). */
static void sphere(float radius) {
  const int slices = 24, stacks = 16;
  int i, j, k;
  glBegin(GL_TRIANGLES);
  for (j = 0; j < stacks; ++j)
    for (i = 0; i < slices; ++i) {
      static const int corner[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
      for (k = 0; k < 6; ++k) {
        float a = 6.2831853f * (float)(i + corner[k][0]) / (float)slices;
        float b = 3.1415927f * ((float)(j + corner[k][1]) / (float)stacks - 0.5f);
        float n[3];
        n[0] = cosf(b) * cosf(a), n[1] = sinf(b), n[2] = cosf(b) * sinf(a);
        glNormal3fv(n);
        glVertex3f(radius * n[0], radius * n[1], radius * n[2]);
      }
    }
  glEnd();
}

static void view(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -0.75, 0.75, 2, 20);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

int main(int argc, char** argv) {
  static const GLfloat s_plane[4] = {0.45f, 0.1f, 0, 0.5f}, t_plane[4] = {-0.05f, 0.6f, 0.2f, 0.35f};
  static const GLdouble s_eye[4] = {0.3, 0.05, 0.1, 0.5};
  static const GLint t_eye[4] = {0, 1, 0, 1};
  static const GLfloat q_plane[4] = {0.2f, 0, 0, 1};
  static const GLfloat verts[] = {-1.4f, -0.9f, 0, 1.3f, -0.8f, 0, 1.2f, 0.95f, 0, -1.3f, 0.9f, 0.3f};
  GLfloat v[4];
  conf_init(argc, argv, W, H);
  texture();
  view();
  glClearColor(0.1f, 0.1f, 0.1f, 1);

  /* Object linear on s and t, under a rotation: the coordinates follow the object. */
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenf(GL_T, GL_TEXTURE_GEN_MODE, (GLfloat)GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, s_plane);
  glTexGenfv(GL_T, GL_OBJECT_PLANE, t_plane);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  glTranslatef(0, 0, -4);
  glRotatef(-35, 1, 0, 0);
  glRotatef(20, 0, 0, 1);
  grid();
  conf_frame("object_linear");

  /* Eye linear: planes given under one modelview, drawn under another (the texture
   * stays in the eye's frame), with a texture matrix after generation. */
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glLoadIdentity();
  glTranslatef(0.3f, 0, -3);
  glRotatef(15, 0, 0, 1);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGendv(GL_S, GL_EYE_PLANE, s_eye);
  glTexGeniv(GL_T, GL_EYE_PLANE, t_eye);
  gen_values("eye_plane_s", GL_S, GL_EYE_PLANE, 4);
  gen_values("eye_plane_t", GL_T, GL_EYE_PLANE, 4);
  glLoadIdentity();
  glTranslatef(0, 0, -4.5f);
  glRotatef(40, 0, 1, 0);
  glMatrixMode(GL_TEXTURE);
  glScalef(1.5f, 0.8f, 1);
  glTranslatef(0.1f, 0.2f, 0);
  glMatrixMode(GL_MODELVIEW);
  grid();
  conf_frame("eye_linear");
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);

  /* Sphere map on a lit-less sphere and a tilted grid with one normal. */
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glLoadIdentity();
  glTranslatef(-0.7f, 0.1f, -4);
  glRotatef(30, 1, 1, 0);
  sphere(0.9f);
  glLoadIdentity();
  glTranslatef(1.2f, -0.2f, -5);
  glRotatef(-50, 0, 1, 0);
  glScalef(0.5f, 0.8f, 1);
  glNormal3f(0.3f, 0.2f, 0.93f);
  grid();
  conf_frame("sphere_map");

  /* GL 1.3's normal map on s and reflection map on t, through a texture matrix that
   * takes [-1, 1] to [0, 1]; GL_NORMALIZE on, with normals scaled by the modelview. */
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_NORMALIZE);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.5f, 0.5f, 0);
  glScalef(0.5f, 0.5f, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -4);
  glRotatef(-25, 0, 1, 0);
  glScalef(1.4f, 1, 1);
  sphere(0.9f);
  conf_frame("cube_modes");
  glDisable(GL_NORMALIZE);
  glMatrixMode(GL_TEXTURE);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glDisable(GL_DEPTH_TEST);

  /* Mixed: t from glTexCoord (per vertex), s object linear, q object linear
   * (projective), compiled into a display list, then through vertex arrays. */
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_TEXTURE_GEN_T);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_Q, GL_OBJECT_PLANE, q_plane);
  glEnable(GL_TEXTURE_GEN_Q);
  glLoadIdentity();
  glTranslatef(-0.8f, 0.35f, -4);
  glScalef(0.5f, 0.45f, 1);
  glNewList(1, GL_COMPILE);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0.1f), glVertex2f(-1.5f, -1);
  glTexCoord2f(0, 0.3f), glVertex2f(1.5f, -1);
  glTexCoord2f(0, 0.9f), glVertex2f(1.5f, 1);
  glTexCoord2f(0, 0.7f), glVertex2f(-1.5f, 1);
  glEnd();
  glEndList();
  glCallList(1);
  glLoadIdentity();
  glTranslatef(0.7f, -0.4f, -4);
  glScalef(0.6f, 0.5f, 1);
  glTexCoord2f(0.2f, 0.65f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, verts);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  glDisableClientState(GL_VERTEX_ARRAY);
  conf_frame("mixed_list_arrays");

  /* The raster position's coordinates: generated too (s and q here). */
  glLoadIdentity();
  glTranslatef(0, 0, -4);
  glTexCoord4f(0.25f, 0.5f, 0.75f, 2);
  glRasterPos3f(0.5f, -0.25f, 0.5f);
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, v);
  values4("raster_texcoord", v, 4);

  /* Queries: modes, planes, enables, as floats and as integers. */
  gen_values("mode_s", GL_S, GL_TEXTURE_GEN_MODE, 1);
  gen_values("mode_t", GL_T, GL_TEXTURE_GEN_MODE, 1);
  gen_values("mode_r", GL_R, GL_TEXTURE_GEN_MODE, 1);
  gen_values("object_plane_s", GL_S, GL_OBJECT_PLANE, 4);
  gen_values("object_plane_r", GL_R, GL_OBJECT_PLANE, 4);
  gen_values("eye_plane_q", GL_Q, GL_EYE_PLANE, 4);
  {
    GLint iv[4] = {0, 0, 0, 0};
    GLdouble dv[4] = {0, 0, 0, 0};
    glGetTexGeniv(GL_T, GL_EYE_PLANE, iv);
    v[0] = (GLfloat)iv[0], v[1] = (GLfloat)iv[1], v[2] = (GLfloat)iv[2], v[3] = (GLfloat)iv[3];
    values4("eye_plane_t_int", v, 4);
    glGetTexGendv(GL_S, GL_TEXTURE_GEN_MODE, dv);
    conf_value("mode_s_double", dv[0]);
  }
  conf_value("enabled_s", glIsEnabled(GL_TEXTURE_GEN_S));
  conf_value("enabled_t", glIsEnabled(GL_TEXTURE_GEN_T));
  conf_value("enabled_q", glIsEnabled(GL_TEXTURE_GEN_Q));
  conf_value("error_none", glGetError());

  /* The attribute stacks: GL_ENABLE_BIT brings back the enables, GL_TEXTURE_BIT the
   * modes and planes too. */
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_R);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glPopAttrib();
  conf_value("pop_enable_s", glIsEnabled(GL_TEXTURE_GEN_S));
  conf_value("pop_enable_r", glIsEnabled(GL_TEXTURE_GEN_R));
  gen_values("pop_enable_mode_s", GL_S, GL_TEXTURE_GEN_MODE, 1);
  glPushAttrib(GL_TEXTURE_BIT);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, t_plane);
  glDisable(GL_TEXTURE_GEN_Q);
  glPopAttrib();
  gen_values("pop_texture_mode_s", GL_S, GL_TEXTURE_GEN_MODE, 1);
  gen_values("pop_texture_plane_s", GL_S, GL_OBJECT_PLANE, 4);
  conf_value("pop_texture_enable_q", glIsEnabled(GL_TEXTURE_GEN_Q));

  /* Errors: a mode a coordinate may not take, a bad coordinate, a bad name, inside
   * glBegin/glEnd; a plane through the one-value form is (v 0 0 0), no error, in Mesa. */
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  conf_value("error_sphere_r", glGetError());
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  conf_value("error_normal_q", glGetError());
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_LINEAR);
  conf_value("error_mode", glGetError());
  glTexGeni(GL_S + 4, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  conf_value("error_coord", glGetError());
  glTexGenf(GL_S, GL_EYE_PLANE, 1);
  conf_value("error_plane_scalar", glGetError());
  gen_values("eye_plane_scalar", GL_S, GL_EYE_PLANE, 4);
  glTexGenfv(GL_S, GL_TEXTURE_ENV_MODE, s_plane);
  conf_value("error_pname", glGetError());
  glGetTexGenfv(GL_S, GL_TEXTURE_ENV_MODE, v);
  conf_value("error_get_pname", glGetError());
  glBegin(GL_POINTS);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glEnd();
  conf_value("error_in_begin", glGetError());
  gen_values("mode_s_after_errors", GL_S, GL_TEXTURE_GEN_MODE, 1);
  return conf_end();
}
