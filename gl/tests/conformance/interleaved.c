/* glInterleavedArrays: each of the 14 formats (GL 1.5 Table 2.5) draws a lit, textured
 * or coloured fan of asymmetric triangles from one interleaved record array, packed
 * (stride 0) and with 12 bytes of padding a record, into its own viewport; a
 * glDrawElements and a glArrayElement from the same arrays; the arrays each format
 * enables and disables (glIsEnabled) and their sizes, types and strides (glGet); an
 * edge-flag array turned off; the errors. Frames and values compared with Mesa. */
#include "harness.h"

#define VERTS 5
static float records[VERTS * 32]; /* room for 15 floats + 12 bytes a vertex */

/* Vertex k of the fan: position, texture coordinates, colour and normal. */
static void attributes(int k, float* v, float* t, float* c, float* n) {
  static const float xy[VERTS][2] = {{-0.8f, -0.7f}, {0.7f, -0.9f}, {0.9f, 0.2f}, {0.1f, 0.85f}, {-0.9f, 0.4f}};
  v[0] = xy[k][0], v[1] = xy[k][1], v[2] = 0.1f * (float)k - 0.2f, v[3] = k == 2 ? 1.25f : 1;
  t[0] = 0.2f + 0.3f * (float)k, t[1] = 1.1f - 0.25f * (float)k, t[2] = 0, t[3] = k == 3 ? 2 : 1;
  c[0] = k % 2 ? 1.0f : 0.2f, c[1] = 0.25f * (float)k, c[2] = k == 1 ? 0.1f : 0.9f, c[3] = 1 - 0.1f * (float)k;
  n[0] = 0.2f * (float)k - 0.4f, n[1] = 0.3f, n[2] = 0.8f;
}

/* Records for `format` at `stride` bytes (0: packed), built by hand from Table 2.5. */
static void fill(GLenum format, int stride) {
  const int t = format == GL_T2F_V3F || format == GL_T2F_C4UB_V3F || format == GL_T2F_C3F_V3F ||
                        format == GL_T2F_N3F_V3F || format == GL_T2F_C4F_N3F_V3F
                    ? 2
                    : format == GL_T4F_V4F || format == GL_T4F_C4F_N3F_V4F ? 4 : 0;
  const int cu = format == GL_C4UB_V2F || format == GL_C4UB_V3F || format == GL_T2F_C4UB_V3F;
  const int cf = format == GL_C3F_V3F || format == GL_T2F_C3F_V3F ? 3
                 : format == GL_C4F_N3F_V3F || format == GL_T2F_C4F_N3F_V3F || format == GL_T4F_C4F_N3F_V4F ? 4 : 0;
  const int nrm = format == GL_N3F_V3F || format == GL_C4F_N3F_V3F || format == GL_T2F_N3F_V3F ||
                  format == GL_T2F_C4F_N3F_V3F || format == GL_T4F_C4F_N3F_V4F;
  const int vs = format == GL_V2F || format == GL_C4UB_V2F ? 2 : format == GL_T4F_V4F || format == GL_T4F_C4F_N3F_V4F ? 4 : 3;
  const int floats = t + cu + cf + 3 * nrm + vs;
  const int step = stride ? stride : floats * 4;
  int k, i;
  memset(records, 0, sizeof records);
  for (k = 0; k < VERTS; ++k) {
    float v[4], tc[4], c[4], n[3];
    float* r = (float*)((char*)records + k * step);
    attributes(k, v, tc, c, n);
    for (i = 0; i < t; ++i) *r++ = tc[i];
    if (cu) {
      unsigned char* b = (unsigned char*)r;
      for (i = 0; i < 4; ++i) b[i] = (unsigned char)(c[i] * 255 + 0.5f);
      ++r;
    }
    for (i = 0; i < cf; ++i) *r++ = c[i];
    for (i = 0; i < 3 * nrm; ++i) *r++ = n[i];
    for (i = 0; i < vs; ++i) *r++ = v[i];
  }
}

int main(int argc, char** argv) {
  static const GLenum formats[14] = {GL_V2F, GL_V3F, GL_C4UB_V2F, GL_C4UB_V3F, GL_C3F_V3F, GL_N3F_V3F,
                                     GL_C4F_N3F_V3F, GL_T2F_V3F, GL_T4F_V4F, GL_T2F_C4UB_V3F, GL_T2F_C3F_V3F,
                                     GL_T2F_N3F_V3F, GL_T2F_C4F_N3F_V3F, GL_T4F_C4F_N3F_V4F};
  static const GLubyte texels[4 * 4] = {255, 255, 255, 255, 40, 80, 200, 255, 200, 60, 30, 255, 90, 220, 90, 255};
  static const GLubyte indices[6] = {4, 0, 1, 1, 2, 3};
  static const GLboolean edges[VERTS] = {1, 0, 1, 0, 1};
  static const float light[4] = {0.3f, 0.5f, 1, 0};
  const int size = 40;
  int pass, f;
  char name[64];
  GLint v;
  conf_init(argc, argv, 7 * size, 4 * size);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glEnable(GL_DEPTH_TEST);
  glEdgeFlagPointer(0, edges);
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (pass = 0; pass < 2; ++pass) {
    for (f = 0; f < 14; ++f) {
      const GLenum format = formats[f];
      const int stride = pass ? 0 : 15 * 4 + 12;
      const int textured = format >= GL_T2F_V3F;
      const int lit = format == GL_N3F_V3F || format == GL_C4F_N3F_V3F || format == GL_T2F_N3F_V3F ||
                      format == GL_T2F_C4F_N3F_V3F || format == GL_T4F_C4F_N3F_V4F;
      glViewport((f % 7) * size, (f / 7 + 2 * pass) * size, size, size);
      glColor4f(0.6f, 0.8f, 0.3f, 1); /* what formats without colours draw with */
      glNormal3f(0, 0, 1);
      glEnableClientState(GL_EDGE_FLAG_ARRAY); /* turned off by each call */
      fill(format, stride);
      glInterleavedArrays(format, stride, records);
      if (lit) glEnable(GL_LIGHTING);
      if (textured) glEnable(GL_TEXTURE_2D);
      if (f % 3 == 0) {
        glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, indices);
      } else if (f % 3 == 1) {
        glDrawArrays(GL_TRIANGLE_FAN, 0, VERTS);
      } else {
        int k;
        glBegin(GL_POLYGON);
        for (k = 0; k < VERTS; ++k) glArrayElement(k);
        glEnd();
      }
      glDisable(GL_LIGHTING);
      glDisable(GL_TEXTURE_2D);
      if (pass == 0) {
        static const GLenum arrays[5] = {GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_NORMAL_ARRAY, GL_TEXTURE_COORD_ARRAY,
                                         GL_EDGE_FLAG_ARRAY};
        static const GLenum gets[9] = {GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_STRIDE, GL_COLOR_ARRAY_SIZE,
                                       GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE, GL_NORMAL_ARRAY_STRIDE,
                                       GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_STRIDE, GL_VERTEX_ARRAY_TYPE};
        int a;
        for (a = 0; a < 5; ++a) {
          snprintf(name, sizeof name, "f%d_enabled%d", f, a);
          conf_value(name, glIsEnabled(arrays[a]));
        }
        for (a = 0; a < 9; ++a) {
          snprintf(name, sizeof name, "f%d_get%d", f, a);
          glGetIntegerv(gets[a], &v);
          conf_value(name, v);
        }
      }
      snprintf(name, sizeof name, "f%d_%d_error", f, pass);
      conf_value(name, glGetError());
    }
  }
  conf_frame("formats");
  glInterleavedArrays(GL_V2F + 14, 0, records);
  conf_value("bad_format", glGetError());
  glInterleavedArrays(GL_V3F, -4, records);
  conf_value("negative_stride", glGetError());
  glGetIntegerv(GL_VERTEX_ARRAY_SIZE, &v);
  conf_value("unchanged_size", v);
  return conf_end();
}
