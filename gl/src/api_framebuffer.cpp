// The C entry points of framebuffer objects (framebuffer_objects.cpp) and
// glBlitFramebuffer (blit.cpp), under GL_ARB_framebuffer_object's names and
// GL_EXT_framebuffer_object's / GL_EXT_framebuffer_blit's (the same functions).
// None is compiled into a display list (ARB_framebuffer_object: they execute at once).
#include <GL/gl.h>

#include "api_entry.hpp"
#include "context.hpp"

extern "C" {

void glGenFramebuffers(GLsizei n, GLuint* ids) { NOW(c.gen_framebuffers(n, ids)); }
void glDeleteFramebuffers(GLsizei n, const GLuint* ids) { NOW(c.delete_framebuffers(n, ids)); }
void glBindFramebuffer(GLenum target, GLuint id) { NOW(c.bind_framebuffer(target, id)); }
GLboolean glIsFramebuffer(GLuint id) {
  GLboolean r = GL_FALSE;
  NOW(if (!c.in_begin_error()) r = c.is_framebuffer(id) ? GL_TRUE : GL_FALSE);
  return r;
}
GLenum glCheckFramebufferStatus(GLenum target) {
  GLenum r = 0;
  NOW(r = c.check_framebuffer_status(target));
  return r;
}
void glFramebufferTexture1D(GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level) {
  NOW(c.framebuffer_texture(target, attachment, textarget, texture, level, 1));
}
void glFramebufferTexture2D(GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level) {
  NOW(c.framebuffer_texture(target, attachment, textarget, texture, level, 2));
}
void glFramebufferTexture3D(GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level,
                            GLint) {
  NOW(c.framebuffer_texture(target, attachment, textarget, texture, level, 3));
}
void glFramebufferTextureLayer(GLenum target, GLenum attachment, GLuint texture, GLint level, GLint) {
  NOW(c.framebuffer_texture(target, attachment, GL_NONE, texture, level, 3));
}
void glFramebufferRenderbuffer(GLenum target, GLenum attachment, GLenum rb_target, GLuint rb) {
  NOW(c.framebuffer_renderbuffer(target, attachment, rb_target, rb));
}
void glGetFramebufferAttachmentParameteriv(GLenum target, GLenum attachment, GLenum pname, GLint* params) {
  NOW(c.get_framebuffer_attachment_parameter(target, attachment, pname, params));
}
void glGenRenderbuffers(GLsizei n, GLuint* ids) { NOW(c.gen_renderbuffers(n, ids)); }
void glDeleteRenderbuffers(GLsizei n, const GLuint* ids) { NOW(c.delete_renderbuffers(n, ids)); }
void glBindRenderbuffer(GLenum target, GLuint id) { NOW(c.bind_renderbuffer(target, id)); }
GLboolean glIsRenderbuffer(GLuint id) {
  GLboolean r = GL_FALSE;
  NOW(if (!c.in_begin_error()) r = c.is_renderbuffer(id) ? GL_TRUE : GL_FALSE);
  return r;
}
void glRenderbufferStorage(GLenum target, GLenum internal, GLsizei w, GLsizei h) {
  NOW(c.renderbuffer_storage(target, 0, internal, w, h));
}
void glRenderbufferStorageMultisample(GLenum target, GLsizei samples, GLenum internal, GLsizei w, GLsizei h) {
  NOW(c.renderbuffer_storage(target, samples, internal, w, h));
}
void glGetRenderbufferParameteriv(GLenum target, GLenum pname, GLint* params) {
  NOW(c.get_renderbuffer_parameter(target, pname, params));
}
void glGenerateMipmap(GLenum target) { NOW(c.generate_mipmap(target)); }
void glBlitFramebuffer(GLint sx0, GLint sy0, GLint sx1, GLint sy1, GLint dx0, GLint dy0, GLint dx1, GLint dy1,
                       GLbitfield mask, GLenum filter) {
  NOW(c.blit_framebuffer(sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, mask, filter));
}

void glGenFramebuffersEXT(GLsizei n, GLuint* ids) { glGenFramebuffers(n, ids); }
void glDeleteFramebuffersEXT(GLsizei n, const GLuint* ids) { glDeleteFramebuffers(n, ids); }
void glBindFramebufferEXT(GLenum target, GLuint id) { glBindFramebuffer(target, id); }
GLboolean glIsFramebufferEXT(GLuint id) { return glIsFramebuffer(id); }
GLenum glCheckFramebufferStatusEXT(GLenum target) { return glCheckFramebufferStatus(target); }
void glFramebufferTexture1DEXT(GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level) {
  glFramebufferTexture1D(target, attachment, textarget, texture, level);
}
void glFramebufferTexture2DEXT(GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level) {
  glFramebufferTexture2D(target, attachment, textarget, texture, level);
}
void glFramebufferTexture3DEXT(GLenum target, GLenum attachment, GLenum textarget, GLuint texture, GLint level,
                               GLint zoffset) {
  glFramebufferTexture3D(target, attachment, textarget, texture, level, zoffset);
}
void glFramebufferRenderbufferEXT(GLenum target, GLenum attachment, GLenum rb_target, GLuint rb) {
  glFramebufferRenderbuffer(target, attachment, rb_target, rb);
}
void glGetFramebufferAttachmentParameterivEXT(GLenum target, GLenum attachment, GLenum pname, GLint* params) {
  glGetFramebufferAttachmentParameteriv(target, attachment, pname, params);
}
void glGenRenderbuffersEXT(GLsizei n, GLuint* ids) { glGenRenderbuffers(n, ids); }
void glDeleteRenderbuffersEXT(GLsizei n, const GLuint* ids) { glDeleteRenderbuffers(n, ids); }
void glBindRenderbufferEXT(GLenum target, GLuint id) { glBindRenderbuffer(target, id); }
GLboolean glIsRenderbufferEXT(GLuint id) { return glIsRenderbuffer(id); }
void glRenderbufferStorageEXT(GLenum target, GLenum internal, GLsizei w, GLsizei h) {
  glRenderbufferStorage(target, internal, w, h);
}
void glRenderbufferStorageMultisampleEXT(GLenum target, GLsizei samples, GLenum internal, GLsizei w, GLsizei h) {
  glRenderbufferStorageMultisample(target, samples, internal, w, h);
}
void glGetRenderbufferParameterivEXT(GLenum target, GLenum pname, GLint* params) {
  glGetRenderbufferParameteriv(target, pname, params);
}
void glGenerateMipmapEXT(GLenum target) { glGenerateMipmap(target); }
void glBlitFramebufferEXT(GLint sx0, GLint sy0, GLint sx1, GLint sy1, GLint dx0, GLint dy0, GLint dx1, GLint dy1,
                          GLbitfield mask, GLenum filter) {
  glBlitFramebuffer(sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, mask, filter);
}

}  // extern "C"
