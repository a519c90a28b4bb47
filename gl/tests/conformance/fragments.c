/* Per-fragment operations: blending with GL's factors, the alpha test, fog (linear,
 * exp, exp2), the scissor test (also for glClear), the colour mask. */
#define GL_GLEXT_PROTOTYPES /* Mesa's <GL/gl.h>: GL 1.4's functions (glext.h) */
#include "harness.h"

int main(int argc, char** argv) {
  static const GLenum src[6] = {GL_SRC_ALPHA, GL_ONE, GL_DST_COLOR, GL_ONE_MINUS_DST_ALPHA, GL_SRC_ALPHA_SATURATE, GL_ZERO};
  static const GLenum dst[6] = {GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO, GL_SRC_COLOR, GL_ONE, GL_ONE_MINUS_SRC_COLOR};
  static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
  int i;
  conf_init(argc, argv, 192, 128);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 192, 0, 128, -10, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();

  /* Blending: a gradient background, then translucent quads with each factor pair. */
  glClearColor(0.2f, 0.3f, 0.4f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_QUADS);
  glColor4f(1, 0, 0, 0.2f);
  glVertex2f(0, 0);
  glColor4f(0, 1, 0, 0.9f);
  glVertex2f(192, 0);
  glColor4f(0, 0, 1, 0.6f);
  glVertex2f(192, 128);
  glColor4f(1, 1, 1, 0.0f);
  glVertex2f(0, 128);
  glEnd();
  glEnable(GL_BLEND);
  for (i = 0; i < 6; ++i) {
    glBlendFunc(src[i], dst[i]);
    glColor4f(0.9f, 0.6f, 0.1f + 0.15f * i, 0.25f + 0.12f * i);
    conf_quad(8.0f + 30 * i, 20, 30.0f + 30 * i, 108, 0);
  }
  glDisable(GL_BLEND);
  conf_frame("blend");

  /* Alpha test: per comparison a band of five quads with alpha 0, 0.25, 0.5, 0.75, 1
   * (reference 0.6, or 0 for GL_EQUAL: no value sits on the reference). */
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_ALPHA_TEST);
  for (i = 0; i < 8; ++i) {
    int k;
    glAlphaFunc(funcs[i], i == 2 ? 0.0f : 0.6f);
    for (k = 0; k < 5; ++k) {
      glColor4f(0.2f + 0.2f * k, 0.8f, 1.0f - 0.15f * k, 0.25f * k);
      conf_quad(10.0f + 34 * k, 4.0f + 15 * i, 40.0f + 34 * k, 16.0f + 15 * i, 0);
    }
  }
  glDisable(GL_ALPHA_TEST);
  conf_frame("alpha_test");

  /* Fog: three rows of quads going away from the eye, one per fog mode. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-0.15, 0.15, -0.1, 0.1, 0.2, 40);
  glMatrixMode(GL_MODELVIEW);
  glClearColor(0.5f, 0.5f, 0.6f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_FOG);
  {
    const GLfloat fog_color[4] = {0.5f, 0.5f, 0.6f, 1};
    glFogfv(GL_FOG_COLOR, fog_color);
  }
  for (i = 0; i < 3; ++i) {
    int k;
    glFogi(GL_FOG_MODE, i == 0 ? GL_LINEAR : i == 1 ? GL_EXP : GL_EXP2);
    glFogf(GL_FOG_START, 2);
    glFogf(GL_FOG_END, 25);
    glFogf(GL_FOG_DENSITY, i == 1 ? 0.12f : 0.09f);
    for (k = 0; k < 8; ++k) {
      glColor3f(k % 2 ? 1.0f : 0.1f, 0.3f + 0.08f * k, i == 2 ? 1.0f : 0.2f);
      glLoadIdentity();
      glTranslatef((-3.0f + 3.0f * i) * (1 + 0.4f * k), -2.5f + 0.9f * k, -5.0f - 3.0f * k);
      conf_quad(-0.8f, 0, 0.8f, 1.2f, 0);
    }
  }
  glDisable(GL_FOG);
  glDisable(GL_DEPTH_TEST);
  conf_frame("fog");

  /* Scissor (drawing and clearing) and the colour mask. */
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 192, 0, 128, -10, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.1f, 0.1f, 0.1f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(20, 10, 60, 50);
  glClearColor(0.8f, 0.2f, 0.2f, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glScissor(50, 30, 100, 80);
  glColor3f(0.2f, 0.9f, 0.3f);
  conf_quad(0, 0, 192, 128, 0);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
  glColor3f(0.9f, 0.9f, 0.9f);
  conf_quad(120, 5, 180, 60, 0);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  conf_frame("scissor_mask");

  /* GL 1.4's blending: the constant colour and its factors, separate alpha factors,
   * the five equations, glMultiDrawArrays. (The frame only: llvmpipe blends in 8-bit
   * fixed point, a step off float blending now and then.) */
  {
    static const GLenum eq[5] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
    static const GLenum f[4] = {GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA,
                                GL_ONE_MINUS_CONSTANT_ALPHA};
    static const GLfloat strip[8] = {0, 100, 192, 100, 0, 128, 192, 128};
    static const GLint first[2] = {0, 2};
    static const GLsizei count[2] = {3, 2};
    GLint v[4];
    GLfloat c[4];
    int j;
    glClearColor(0.6f, 0.3f, 0.5f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendColor(0.25f, 0.5f, 0.75f, 0.4f);
    for (i = 0; i < 5; ++i)
      for (j = 0; j < 4; ++j) {
        glBlendEquation(eq[i]);
        glBlendFuncSeparate(f[j], f[3 - j], GL_SRC_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
        glColor4f(0.9f, 0.5f, 0.2f, 0.7f);
        conf_quad(i * 38.0f, j * 24.0f, i * 38.0f + 36, j * 24.0f + 22, 0);
      }
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ZERO);
    glVertexPointer(2, GL_FLOAT, 0, strip);
    glEnableClientState(GL_VERTEX_ARRAY);
    glColor4f(0.2f, 0.4f, 1, 1);
    glMultiDrawArrays(GL_TRIANGLES, first, count, 1);
    glMultiDrawArrays(GL_TRIANGLES, first, count, -1);
    conf_value("multi_draw_negative", glGetError());
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisable(GL_BLEND);
    conf_frame("blend14");
    glBlendColor(2, -1, 0.5f, 0.25f);
    glGetFloatv(GL_BLEND_COLOR, c);
    conf_value("blend_color_r", c[0]);
    conf_value("blend_color_g", c[1]);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, v);
    conf_value("blend_src_alpha", v[0]);
    glGetIntegerv(GL_BLEND_DST_ALPHA, v);
    conf_value("blend_dst_alpha", v[0]);
    glGetIntegerv(GL_BLEND_EQUATION, v);
    conf_value("blend_equation", v[0]);
    glBlendEquation(GL_ONE);
    conf_value("blend_equation_bad", glGetError());
  }
  return conf_end();
}
