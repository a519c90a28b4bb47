// What the GLX vendor sets in pGL's current context (pgl_bridge.cpp).
#pragma once

// A double-buffered drawable: glGet answers GL_DOUBLEBUFFER 1, GL_DRAW_BUFFER GL_BACK.
void velocity_glx_set_double_buffered(bool double_buffered);
// A configuration with samples: k x k samples a pixel (1: none).
void velocity_glx_set_samples_side(int k);
// Records a GL error in the current context (none current: nothing).
void velocity_glx_gl_error(unsigned error);
// glXSwapBuffers: the back buffer's colour becomes the front's too.
void velocity_glx_swap_buffers();
// The front buffer of a double-buffered context that draws into it (glDrawBuffer
// GL_FRONT or GL_FRONT_AND_BACK), as BGRA top row first, width x height; false (nothing
// written) when it does not or the size differs.
bool velocity_glx_front(unsigned char* bgra, int width, int height);
