/* Vertex arrays (the four pointers, glDrawArrays, glDrawElements, glArrayElement) and
 * display lists (GL_COMPILE, GL_COMPILE_AND_EXECUTE, nested lists, glCallLists with a
 * list base, glDeleteLists), culling, front face, polygon modes and polygon offset. */
#include "harness.h"

static const GLfloat verts[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
/* Colours affine in the position, so that they do not depend on the diagonal a quad is
 * split along (Mesa splits quads differently in immediate mode and in display lists). */
static const GLubyte colors[8][4] = {{0, 0, 0, 255},     {255, 0, 0, 255},   {255, 255, 0, 255}, {0, 255, 0, 255},
                                     {0, 0, 255, 255},   {255, 0, 255, 255}, {255, 255, 255, 255}, {0, 255, 255, 255}};
static const GLushort faces[24] = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 2, 3, 7, 6, 0, 4, 7, 3, 1, 2, 6, 5};

int main(int argc, char** argv) {
  GLuint base;
  int i;
  conf_init(argc, argv, 200, 150);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45, 200.0 / 150.0, 1, 30);
  glMatrixMode(GL_MODELVIEW);

  glVertexPointer(3, GL_FLOAT, 0, verts);
  glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);

  /* Lists: 1 = an indexed cube (arrays read at compile time), 2 = a ring of three
   * cubes calling list 1, 3.. = small translations for glCallLists. */
  base = glGenLists(5);
  glNewList(base, GL_COMPILE);
  glDrawElements(GL_QUADS, 24, GL_UNSIGNED_SHORT, faces);
  glEndList();
  glNewList(base + 1, GL_COMPILE);
  for (i = 0; i < 3; ++i) {
    glPushMatrix();
    glRotatef(120.0f * i, 0, 1, 0);
    glTranslatef(2.2f, 0, 0);
    glScalef(0.5f, 0.5f, 0.5f);
    glCallList(base);
    glPopMatrix();
  }
  glEndList();
  glNewList(base + 2, GL_COMPILE);
  glTranslatef(0, 1.2f, 0);
  glEndList();
  glNewList(base + 3, GL_COMPILE);
  glTranslatef(0, -2.4f, 0);
  glEndList();

  /* Frame 1: arrays drawn directly, then the lists. */
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glLoadIdentity();
  glTranslatef(0, 0, -9);
  glRotatef(25, 1, 0, 0);
  glRotatef(30, 0, 1, 0);
  glCallList(base + 1);
  {
    const GLubyte offsets[2] = {2, 3};
    glListBase(base);
    glCallLists(2, GL_UNSIGNED_BYTE, offsets); /* up 1.2, then down 2.4 */
    glListBase(0);
  }
  glPushMatrix();
  glScalef(0.4f, 0.4f, 0.4f);
  glDrawArrays(GL_QUADS, 0, 8); /* the cube's two z faces from the arrays in order */
  glPopMatrix();
  glTranslatef(0, 2.4f, 0);
  glBegin(GL_TRIANGLES);
  glArrayElement(0);
  glArrayElement(5);
  glArrayElement(6);
  glEnd();
  /* A lit, textured strip from all four arrays (float normals, short texture
   * coordinates, double positions, float colours with stride). */
  {
    static const GLdouble pos[8][3] = {{-1, -0.5, 0}, {-1, 0.5, 0}, {-0.3, -0.6, 0.3}, {-0.3, 0.6, 0.3},
                                       {0.3, -0.6, 0.3}, {0.3, 0.6, 0.3}, {1, -0.5, 0}, {1, 0.5, 0}};
    static const GLfloat nrm[8][3] = {{-0.4f, 0, 1}, {-0.4f, 0, 1}, {-0.1f, 0, 1}, {-0.1f, 0, 1},
                                      {0.1f, 0, 1}, {0.1f, 0, 1}, {0.4f, 0, 1}, {0.4f, 0, 1}};
    static const GLshort tc[8][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 0}, {2, 1}, {3, 0}, {3, 1}};
    static const GLfloat col[8][5] = {{1, 1, 1, 1, 0}, {1, 0.5f, 0.5f, 1, 0}, {0.5f, 1, 0.5f, 1, 0}, {1, 1, 1, 1, 0},
                                      {0.5f, 0.5f, 1, 1, 0}, {1, 1, 0.5f, 1, 0}, {1, 1, 1, 1, 0}, {0.5f, 1, 1, 1, 0}};
    static GLubyte texels[4 * 4 * 3];
    const GLfloat light_dir[4] = {0.3f, 0.4f, 1, 0};
    GLuint tex;
    int t;
    for (t = 0; t < 16; ++t) texels[3 * t] = (GLubyte)(t % 2 ? 255 : 60), texels[3 * t + 1] = (GLubyte)(t / 4 * 60), texels[3 * t + 2] = 200;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glLightfv(GL_LIGHT0, GL_POSITION, light_dir);
    glLoadIdentity();
    glTranslatef(0, -2.2f, -7);
    glVertexPointer(3, GL_DOUBLE, 0, pos);
    glNormalPointer(GL_FLOAT, 0, nrm);
    glTexCoordPointer(2, GL_SHORT, 0, tc);
    glColorPointer(4, GL_FLOAT, 5 * sizeof(GLfloat), col);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 8);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &tex);
    glVertexPointer(3, GL_FLOAT, 0, verts);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
  }
  conf_frame("arrays_lists");

  /* Frame 2: COMPILE_AND_EXECUTE, culling, front face, polygon modes and offset. */
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glLoadIdentity();
  glTranslatef(-1.8f, 0, -8);
  glRotatef(35, 1, 1, 0);
  glNewList(base + 4, GL_COMPILE_AND_EXECUTE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glCallList(base);
  glEndList();
  glTranslatef(3.6f, 0, 0);
  glFrontFace(GL_CW);
  glCallList(base); /* now the far faces are drawn */
  glFrontFace(GL_CCW);
  glDisable(GL_CULL_FACE);
  glTranslatef(-1.8f, -1.8f, 0);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  glPointSize(3);
  glScalef(0.6f, 0.6f, 0.6f);
  glCallList(base);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  /* Polygon offset: a quad coplanar with a face, pushed in front. */
  glTranslatef(0, 3.5f, 0);
  glDisableClientState(GL_COLOR_ARRAY);
  glColor3f(0.3f, 0.3f, 0.9f);
  glDrawRangeElements(GL_QUADS, 4, 7, 4, GL_UNSIGNED_SHORT, faces + 4); /* GL 1.2: indices 4-7 */
  glDrawRangeElements(GL_QUADS, 7, 4, 4, GL_UNSIGNED_SHORT, faces + 4); /* end < start: nothing drawn */
  conf_value("range_elements_reversed_error", glGetError());
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1, -2);
  glColor3f(1, 0.6f, 0.1f);
  glBegin(GL_QUADS);
  glVertex3f(-0.5f, -0.5f, 1);
  glVertex3f(0.5f, -0.5f, 1);
  glVertex3f(0.5f, 0.5f, 1);
  glVertex3f(-0.5f, 0.5f, 1);
  glEnd();
  glDisable(GL_POLYGON_OFFSET_FILL);
  conf_frame("modes_offset");

  /* A draw from the arrays compiled into a list runs whole or not at all: called
   * between glBegin and glEnd it raises GL_INVALID_OPERATION. */
  {
    GLuint draw = glGenLists(1);
    glNewList(draw, GL_COMPILE);
    glDrawArrays(GL_QUADS, 0, 4);
    glEndList();
    glBegin(GL_QUADS);
    glCallList(draw);
    glEnd();
    conf_value("list_draw_inside_begin_error", glGetError());
    glDeleteLists(draw, 1);
  }
  glDeleteLists(base, 5);
  conf_value("is_list_after_delete", glIsList(base));
  return conf_end();
}
