/* Clears an OSMesa buffer with the installed pGL, found as velocity::gl (the same name
   the target has in Velocity's own tree), and checks the pixel it reads back. */
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <stdio.h>

int main(void) {
  static unsigned char pixels[8 * 8 * 4];
  unsigned char rgba[4] = {0, 0, 0, 0};
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
  if (!ctx || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 8, 8)) return fprintf(stderr, "no context\n"), 1;
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glReadPixels(3, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  OSMesaDestroyContext(ctx);
  if (rgba[0] != 255 || rgba[1] != 0) return fprintf(stderr, "read back %d %d %d\n", rgba[0], rgba[1], rgba[2]), 1;
  printf("downstream_gl: cleared and read back through velocity::gl\n");
  return 0;
}
