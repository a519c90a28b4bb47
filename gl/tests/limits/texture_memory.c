/* A frame that is never flushed does not keep every texture it drew with: 2000 textures
 * of 512x512 (2 GB of texels) each drawn once and deleted, as piglit's
 * streaming-texture-leak does, and no glFlush. pGL keeps at most 256 MB of them for the
 * pending frame and runs the frame past that; the process's peak memory stays far below
 * 2 GB. The last texture's colour is on screen (the image is the same). */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>

int main(void) {
  enum { kSize = 512, kTextures = 2000, kW = 64, kH = 64 };
  static unsigned char buffer[kW * kH * 4];
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, kW, kH)) return 2;
  unsigned char* texels = malloc(kSize * kSize * 4);
  if (!texels) return 2;
  glEnable(GL_TEXTURE_2D);
  for (int i = 0; i < kTextures; ++i) {
    for (int p = 0; p < kSize * kSize; ++p) texels[p * 4] = (unsigned char)i, texels[p * 4 + 1] = 7,
                                            texels[p * 4 + 2] = 200, texels[p * 4 + 3] = 255;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, kSize, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glRectf(-1, -1, 1, 1);
    glDeleteTextures(1, &tex);
  }
  glFinish();
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  const long peak_mb = usage.ru_maxrss / 1024;
  const unsigned char* p = buffer + (kH / 2 * kW + kW / 2) * 4;
  printf("peak memory %ld MB for %d MB of textures; centre pixel %d %d %d\n", peak_mb, kTextures, p[0], p[1], p[2]);
  free(texels);
  OSMesaDestroyContext(ctx);
  if (p[0] != (kTextures - 1) % 256 || p[1] != 7 || p[2] != 200) return 1;
  return peak_mb < 1024 ? 0 : 1;
}
