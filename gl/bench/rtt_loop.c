/* A render-to-texture loop, for framebuffer objects' cost (docs/gl.md): N times, a
 * 512x512 RGBA texture drawn into through an FBO (one triangle), then drawn onto a
 * 512x512 window with glFinish; built against Velocity (gl_rtt_loop) and Mesa
 * (gl_rtt_loop_mesa). Time it from outside, CPU time:
 *   perf stat -e task-clock build/gl/bench/gl_rtt_loop 100   (and with 0: the set-up)
 * Prints the centre pixel's red and glGetError. */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char** argv) {
  static unsigned char buf[512 * 512 * 4];
  const int n = argc > 1 ? atoi(argv[1]) : 100;
  OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  GLuint tex, fbo;
  int i;
  if (!c || !OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 512, 512)) return 1;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 512, 512, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  for (i = 0; i < n; ++i) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glDisable(GL_TEXTURE_2D);
    glColor3f((float)(i % 7) / 7.0f, 0.5f, 1.0f - (float)(i % 5) / 5.0f);
    glBegin(GL_TRIANGLES);
    glVertex2f(-1, -1), glVertex2f(1, -1), glVertex2f((float)(i % 9) / 9.0f, 1);
    glEnd();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0), glVertex2f(-1, -1);
    glTexCoord2f(1, 0), glVertex2f(1, -1);
    glTexCoord2f(1, 1), glVertex2f(1, 1);
    glTexCoord2f(0, 1), glVertex2f(-1, 1);
    glEnd();
    glFinish();
  }
  printf("centre_red=%d error=%d\n", buf[4 * (256 * 512 + 256)], (int)glGetError());
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  OSMesaDestroyContext(c);
  return 0;
}
