/* OSMesa's calls beyond making a context current: OSMesaGetColorBuffer (of the current
 * context, and of one never made current), OSMesaGetProcAddress (GL and OSMesa functions,
 * called through the addresses it gives: the frame is drawn by them), OSMesaColorClamp
 * (off, with colours beyond 1 drawn into the 8-bit buffer). */
#include "harness.h"

typedef void(GLAPIENTRY* clear_color_fn)(GLclampf, GLclampf, GLclampf, GLclampf);
typedef void(GLAPIENTRY* clear_fn)(GLbitfield);
typedef void(GLAPIENTRY* color_fn)(GLfloat, GLfloat, GLfloat);
typedef void(GLAPIENTRY* rect_fn)(GLfloat, GLfloat, GLfloat, GLfloat);
typedef OSMesaContext(GLAPIENTRY* current_fn)(void);
/* (Through void (*)(void), which casts to any function type without a warning.) */
#define PROC(type, name) ((type)(void (*)(void))OSMesaGetProcAddress(name))

int main(int argc, char** argv) {
  GLint width = -1, height = -1, format = -1;
  void* buffer = NULL;
  OSMesaContext other;
  clear_color_fn clear_color;
  clear_fn clear;
  color_fn color;
  rect_fn rect;
  current_fn current;
  conf_init(argc, argv, 64, 48);

  conf_value("color_buffer", OSMesaGetColorBuffer(conf_ctx, &width, &height, &format, &buffer));
  conf_value("color_buffer_width", width);
  conf_value("color_buffer_height", height);
  conf_value("color_buffer_rgba", format == OSMESA_RGBA);
  conf_value("color_buffer_is_ours", buffer == (void*)conf_buffer);
  other = OSMesaCreateContextExt(OSMESA_BGRA, 16, 0, 0, NULL);
  width = height = format = -1;
  conf_value("other_color_buffer", OSMesaGetColorBuffer(other, &width, &height, &format, &buffer));
  conf_value("other_width", width);
  conf_value("other_buffer_null", buffer == NULL);
  OSMesaDestroyContext(other);

  clear_color = PROC(clear_color_fn, "glClearColor");
  clear = PROC(clear_fn, "glClear");
  color = PROC(color_fn, "glColor3f");
  rect = PROC(rect_fn, "glRectf");
  current = PROC(current_fn, "OSMesaGetCurrentContext");
  conf_value("proc_gl", clear_color && clear && color && rect);
  conf_value("proc_osmesa_current", current && current() == conf_ctx);
  conf_value("proc_color_clamp", OSMesaGetProcAddress("OSMesaColorClamp") != NULL);
  conf_value("proc_get_color_buffer", OSMesaGetProcAddress("OSMesaGetColorBuffer") != NULL);
  conf_value("proc_buffer_data", OSMesaGetProcAddress("glBufferData") != NULL);
  if (!clear_color || !clear || !color || !rect) return conf_end();
  clear_color(0.2f, 0.1f, 0.3f, 1);
  clear(GL_COLOR_BUFFER_BIT);
  OSMesaColorClamp(GL_FALSE);
  color(1.6f, 0.4f, -0.5f);
  rect(-0.8f, -0.6f, 0.1f, 0.7f);
  color(0.3f, 2.0f, 0.9f);
  rect(0.2f, -0.9f, 0.9f, 0.2f);
  OSMesaColorClamp(GL_TRUE);
  conf_value("gl_error", glGetError());
  conf_frame("through_procs");
  return conf_end();
}
