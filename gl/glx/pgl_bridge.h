// What the GLX vendor sets in pGL's current context (pgl_bridge.cpp).
#pragma once

// A double-buffered drawable: glGet answers GL_DOUBLEBUFFER 1, GL_DRAW_BUFFER GL_BACK.
void velocity_glx_set_double_buffered(bool double_buffered);
// Records a GL error in the current context (none current: nothing).
void velocity_glx_gl_error(unsigned error);
