/* GL 1.5's buffer objects: vertex arrays and indices read from buffers.
 *
 * Frames: one buffer holding positions, colours (unsigned bytes) and normals (shorts)
 * at odd offsets and an odd stride, drawn lit with glDrawArrays; the same through
 * glDrawElements with unsigned byte, short and int indices at offsets in an element
 * buffer, glMultiDrawElements with offsets, glArrayElement between glBegin and glEnd,
 * colours from the client's memory beside positions from a buffer, data written
 * through glMapBuffer and replaced in part with glBufferSubData, a display list
 * compiled from a buffer (which keeps what the buffer held then), glInterleavedArrays
 * at an offset in a buffer.
 * Values: glGetBufferParameteriv, glGetBufferPointerv, glGetBufferSubData, glIsBuffer,
 * every *_BUFFER_BINDING, glGetPointerv (an offset), bindings reset by glDeleteBuffers,
 * glPushClientAttrib, and the errors. Compared with Mesa. */
#define GL_GLEXT_PROTOTYPES 1
#include "harness.h"

#include <math.h>
#include <stddef.h>

struct vertex {
  GLfloat pos[3];   /* at 0 */
  GLubyte pad;      /* the colour at 13: not aligned */
  GLubyte color[4];
  GLshort normal[3];
  GLubyte tail[5]; /* a stride of 32 */
};

#define N 12
static struct vertex verts[N];

/* A fan around a centre: vertex 0 the centre, 1..N-1 on an asymmetric rim. */
static void make_vertices(float scale) {
  int k;
  memset(verts, 0, sizeof verts);
  for (k = 0; k < N; ++k) {
    const float a = 6.2831853f * (float)(k - 1) / (float)(N - 2);
    const float r = k == 0 ? 0.0f : 0.8f * scale * (1.0f + 0.15f * (float)(k % 3));
    verts[k].pos[0] = k == 0 ? 0.05f : r * cosf(a);
    verts[k].pos[1] = k == 0 ? -0.1f : r * sinf(a) * 0.9f;
    verts[k].pos[2] = k == 0 ? 0.3f : -0.1f * (float)(k % 4);
    verts[k].color[0] = (GLubyte)(40 + 17 * k);
    verts[k].color[1] = (GLubyte)(250 - 19 * k);
    verts[k].color[2] = (GLubyte)(k % 2 ? 220 : 60);
    verts[k].color[3] = 255;
    verts[k].normal[0] = (GLshort)(k == 0 ? 0 : 9000 * cosf(a));
    verts[k].normal[1] = (GLshort)(k == 0 ? 0 : 9000 * sinf(a));
    verts[k].normal[2] = 30000;
  }
}

/* Offsets into the vertex buffer, as gl*Pointer's "pointers". */
#define AT(member) ((const GLvoid*)offsetof(struct vertex, member))

static void point_arrays(void) {
  glVertexPointer(3, GL_FLOAT, sizeof(struct vertex), AT(pos));
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct vertex), AT(color));
  glNormalPointer(GL_SHORT, sizeof(struct vertex), AT(normal));
}

static void quadrant(int i) { glViewport((i % 4) * 40, (i / 4) * 40, 40, 40); }

static void lit(int on) {
  static const GLfloat dir[4] = {0.3f, 0.5f, 1.0f, 0.0f};
  if (!on) {
    glDisable(GL_LIGHTING);
    return;
  }
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, dir);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_NORMALIZE);
}

static void error_value(const char* name) { conf_value(name, glGetError()); }

int main(int argc, char** argv) {
  GLuint bufs[4], vbo, ibo, list;
  GLint iv[4];
  GLvoid* p;
  int i;
  conf_init(argc, argv, 160, 120);
  glClearColor(0.1f, 0.1f, 0.15f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  make_vertices(1.0f);

  conf_value("is_buffer_0", glIsBuffer(0));
  glGenBuffers(4, bufs);
  vbo = bufs[0], ibo = bufs[1];
  conf_value("names_differ", bufs[0] != bufs[1] && bufs[1] != bufs[2] && bufs[0] != 0);
  conf_value("is_buffer_generated", glIsBuffer(vbo));
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  conf_value("is_buffer_bound", glIsBuffer(vbo));
  glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, iv);
  conf_value("size", iv[0]);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_USAGE, iv);
  conf_value("usage", iv[0]);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS, iv);
  conf_value("access", iv[0]);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED, iv);
  conf_value("mapped", iv[0]);
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, iv);
  conf_value("array_binding", iv[0] == (GLint)vbo);

  /* 0: glDrawArrays, lit, from the buffer at odd offsets and stride. */
  point_arrays();
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glGetIntegerv(GL_VERTEX_ARRAY_BUFFER_BINDING, iv);
  conf_value("vertex_binding", iv[0] == (GLint)vbo);
  glGetIntegerv(GL_COLOR_ARRAY_BUFFER_BINDING, iv);
  conf_value("color_binding", iv[0] == (GLint)vbo);
  glGetIntegerv(GL_NORMAL_ARRAY_BUFFER_BINDING, iv);
  conf_value("normal_binding", iv[0] == (GLint)vbo);
  glGetIntegerv(GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, iv);
  conf_value("texcoord_binding", iv[0]);
  glGetPointerv(GL_COLOR_ARRAY_POINTER, &p);
  conf_value("color_pointer_offset", (double)(size_t)p);
  lit(1);
  quadrant(0);
  glDrawArrays(GL_TRIANGLE_FAN, 0, N);
  lit(0);

  /* 1-3: glDrawElements with each index type, at an offset in an element buffer (5: empty). */
  {
    GLubyte ub[8 + N + 1];
    GLushort us[3 + N + 1];
    GLuint ui[1 + N + 1];
    int k;
    memset(ub, 0, sizeof ub);
    memset(us, 0, sizeof us);
    memset(ui, 0, sizeof ui);
    for (k = 0; k <= N; ++k) {
      const int idx = k == N ? 1 : (k * 5) % N; /* a star: every fifth rim vertex */
      ub[8 + k] = (GLubyte)idx, us[3 + k] = (GLushort)idx, ui[1 + k] = (GLuint)idx;
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
    glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, iv);
    conf_value("element_binding", iv[0] == (GLint)ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof ub, ub, GL_STREAM_DRAW);
    quadrant(1);
    glDrawElements(GL_LINE_STRIP, N + 1, GL_UNSIGNED_BYTE, (const GLvoid*)8);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof us, us, GL_DYNAMIC_DRAW);
    quadrant(2);
    glDrawElements(GL_TRIANGLE_STRIP, N, GL_UNSIGNED_SHORT, (const GLvoid*)6);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof ui, ui, GL_STATIC_DRAW);
    quadrant(3);
    glDrawElements(GL_POLYGON, N, GL_UNSIGNED_INT, (const GLvoid*)4);
    /* 4: glMultiDrawElements, two fans' worth of triangles at two offsets. */
    {
      const GLsizei counts[2] = {6, 3};
      const GLvoid* offsets[2] = {(const GLvoid*)4, (const GLvoid*)28};
      quadrant(4);
      glMultiDrawElements(GL_TRIANGLES, counts, GL_UNSIGNED_INT, offsets, 2);
    }
    glGetBufferParameteriv(GL_ELEMENT_ARRAY_BUFFER, GL_BUFFER_SIZE, iv);
    conf_value("element_size", iv[0]);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  }

  /* 6: glArrayElement between glBegin and glEnd, smooth quads from the buffer. */
  quadrant(6);
  glBegin(GL_QUADS);
  for (i = 1; i <= 8; ++i) glArrayElement(i);
  glEnd();

  /* 7: colours from the client's memory, positions from the buffer. */
  {
    GLubyte colors[N * 4];
    for (i = 0; i < N * 4; ++i) colors[i] = (GLubyte)(i * 37 % 256);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    glGetIntegerv(GL_COLOR_ARRAY_BUFFER_BINDING, iv);
    conf_value("client_color_binding", iv[0]);
    glGetIntegerv(GL_VERTEX_ARRAY_BUFFER_BINDING, iv);
    conf_value("vertex_binding_kept", iv[0] == (GLint)vbo);
    quadrant(7);
    glDrawArrays(GL_TRIANGLE_FAN, 0, N);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    point_arrays();
  }

  /* 8: a display list compiled from the buffer keeps what it held then. */
  list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glDrawArrays(GL_TRIANGLE_FAN, 0, N);
  glEndList();

  /* Written through glMapBuffer: the fan at 0.6 of its size. */
  make_vertices(0.6f);
  p = glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
  conf_value("map_not_null", p != NULL);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED, iv);
  conf_value("mapped_now", iv[0]);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS, iv);
  conf_value("access_now", iv[0]);
  {
    GLvoid* q = NULL;
    glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &q);
    conf_value("map_pointer_same", q == p);
  }
  /* Errors while mapped. */
  glDrawArrays(GL_TRIANGLE_FAN, 0, N);
  error_value("draw_mapped");
  glBufferSubData(GL_ARRAY_BUFFER, 0, 4, verts);
  error_value("subdata_mapped");
  glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
  error_value("map_twice");
  if (p) memcpy(p, verts, sizeof verts);
  conf_value("unmap", glUnmapBuffer(GL_ARRAY_BUFFER));
  conf_value("unmap_twice", glUnmapBuffer(GL_ARRAY_BUFFER));
  error_value("unmap_twice_error");
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS, iv);
  conf_value("access_after", iv[0]);

  quadrant(8);
  glCallList(list);
  quadrant(9);
  glDrawArrays(GL_TRIANGLE_FAN, 0, N);

  /* 10: glBufferSubData replaces the first vertices' colours only. */
  {
    struct vertex first[3];
    memcpy(first, verts, sizeof first);
    for (i = 0; i < 3; ++i) first[i].color[0] = 255, first[i].color[1] = 0, first[i].color[2] = 0;
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof first, first);
    error_value("subdata");
    quadrant(10);
    glDrawArrays(GL_TRIANGLE_FAN, 0, N);
    {
      struct vertex back[2];
      glGetBufferSubData(GL_ARRAY_BUFFER, sizeof(struct vertex), sizeof back, back);
      conf_value("read_back_red", back[0].color[0]);
      conf_value("read_back_green", back[1].color[1]);
      conf_value("read_back_x", back[1].pos[0]);
    }
  }

  /* 11: glInterleavedArrays (GL_C3F_V3F) at an offset in another buffer. */
  {
    static const GLfloat rec[] = {0,    0,    0,    /* padding: the records start at 12 */
                                  1,    0.5f, 0,    -0.8f, -0.8f, 0, /* */
                                  0,    1,    0.3f, 0.9f,  -0.5f, 0, /* */
                                  0.2f, 0.2f, 1,    -0.1f, 0.9f,  0};
    glDisableClientState(GL_NORMAL_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, bufs[2]);
    glBufferData(GL_ARRAY_BUFFER, sizeof rec, rec, GL_STATIC_DRAW);
    glInterleavedArrays(GL_C3F_V3F, 0, (const GLvoid*)12);
    quadrant(11);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
    conf_value("interleaved_vertex_offset", (double)(size_t)p);
  }
  /* The current colour after draws from a colour array is the one before them (GL
   * leaves it undefined; Mesa keeps it): a white triangle over quadrant 0's corner. */
  glColor3f(1, 1, 1);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisableClientState(GL_COLOR_ARRAY);
  glViewport(0, 0, 160, 120);
  glBegin(GL_TRIANGLES);
  glVertex3f(-1, -1, 0.9f);
  glVertex3f(-0.9f, -1, 0.9f);
  glVertex3f(-1, -0.85f, 0.9f);
  glEnd();
  {
    GLfloat current[4];
    glGetFloatv(GL_CURRENT_COLOR, current);
    conf_value("current_red_after_arrays", current[0]);
    conf_value("current_green_after_arrays", current[1]);
  }
  conf_frame("drawn");

  /* glPushClientAttrib keeps the array buffer binding; glDeleteBuffers resets bindings. */
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glPopClientAttrib();
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, iv);
  conf_value("popped_binding", iv[0] == (GLint)bufs[2]);
  glDeleteBuffers(1, &bufs[2]);
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, iv);
  conf_value("deleted_binding", iv[0]);
  glGetIntegerv(GL_VERTEX_ARRAY_BUFFER_BINDING, iv);
  conf_value("deleted_vertex_binding", iv[0]);
  conf_value("is_buffer_deleted", glIsBuffer(bufs[2]));
  error_value("after_delete");

  /* Errors. */
  glBindBuffer(GL_TEXTURE_2D, vbo);
  error_value("bind_bad_target");
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBufferData(GL_ARRAY_BUFFER, 16, NULL, GL_STATIC_DRAW);
  error_value("data_none_bound");
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, -1, NULL, GL_STATIC_DRAW);
  error_value("data_negative");
  glBufferData(GL_ARRAY_BUFFER, 16, NULL, GL_RGBA);
  error_value("data_bad_usage");
  glBufferSubData(GL_ARRAY_BUFFER, sizeof verts - 4, 8, verts);
  error_value("subdata_past_end");
  glBufferSubData(GL_ARRAY_BUFFER, -4, 4, verts);
  error_value("subdata_negative");
  glMapBuffer(GL_ARRAY_BUFFER, GL_RGBA);
  error_value("map_bad_access");
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_RGBA, iv);
  error_value("parameter_bad_name");
  glGetBufferParameteriv(GL_ARRAY_BUFFER + 7, GL_BUFFER_SIZE, iv);
  error_value("parameter_bad_target");
  glGenBuffers(-1, bufs);
  error_value("gen_negative");
  glDeleteBuffers(-1, bufs);
  error_value("delete_negative");
  glBegin(GL_POINTS);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glEnd();
  error_value("bind_in_begin");
  /* A buffer of zero bytes maps to a pointer (Mesa's too) and reads nothing. */
  glBufferData(GL_ARRAY_BUFFER, 0, NULL, GL_STATIC_DRAW);
  glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, iv);
  conf_value("empty_size", iv[0]);
  error_value("empty");
  glDeleteBuffers(4, bufs);
  glDeleteLists(list, 1);
  return conf_end();
}
