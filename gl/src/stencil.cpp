// The stencil buffer: glStencilFunc, glStencilOp, glStencilMask, glClearStencil, their
// queries, and the stencil part of each batch's PixelState (the test itself runs in the
// renderer's fixed-function kernel, src/raster/shade_fixed-inl.h). A context has 8
// stencil bits or none (OSMesaCreateContextExt's stencilBits, the GLX configuration);
// without them the test is as if disabled and glClear's stencil bit does nothing, as GL
// says.
#include "context.hpp"

namespace velocity::gl {

namespace {
bool is_compare(GLenum f) { return f >= GL_NEVER && f <= GL_ALWAYS; }

bool is_stencil_op(GLenum op) {
  switch (op) {
    case GL_KEEP: case GL_ZERO: case GL_REPLACE: case GL_INCR: case GL_DECR: case GL_INVERT:
    case GL_INCR_WRAP: case GL_DECR_WRAP:
      return true;
    default: return op == 0;  // (GL_ZERO is 0)
  }
}

StencilOp stencil_op_of(GLenum op) {
  switch (op) {
    case GL_ZERO: return StencilOp::Zero;
    case GL_REPLACE: return StencilOp::Replace;
    case GL_INCR: return StencilOp::Increment;
    case GL_DECR: return StencilOp::Decrement;
    case GL_INVERT: return StencilOp::Invert;
    case GL_INCR_WRAP: return StencilOp::IncrementWrap;
    case GL_DECR_WRAP: return StencilOp::DecrementWrap;
    default: return StencilOp::Keep;
  }
}

// GL clamps the reference (and the clear value is masked) to the buffer's bits.
uint8_t clamp_ref(GLint ref, int bits) { return bits == 0 ? 0 : uint8_t(ref < 0 ? 0 : ref > 255 ? 255 : ref); }
}  // namespace

void Context::stencil_func(GLenum func, GLint ref, GLuint mask) {
  if (in_begin_error()) return;
  if (!is_compare(func)) return error(GL_INVALID_ENUM);
  stencil_.func = func, stencil_.ref = ref, stencil_.value_mask = mask;
  changed();
}

void Context::stencil_op(GLenum fail, GLenum depth_fail, GLenum pass) {
  if (in_begin_error()) return;
  if (!is_stencil_op(fail) || !is_stencil_op(depth_fail) || !is_stencil_op(pass)) return error(GL_INVALID_ENUM);
  stencil_.fail = fail, stencil_.depth_fail = depth_fail, stencil_.pass = pass;
  changed();
}

void Context::stencil_mask(GLuint mask) {
  if (in_begin_error()) return;
  stencil_.write_mask = mask;
  changed();
}

void Context::clear_stencil(GLint s) {
  if (in_begin_error()) return;
  stencil_.clear = s;
}

uint8_t Context::stencil_clear_value() const { return stencil_bits_ ? uint8_t(stencil_.clear & 0xff) : 0; }

void Context::stencil_pixel_state(PixelState& s) const {
  s.stencil_test = stencil_.test && stencil_bits_ > 0;
  if (!s.stencil_test) return;
  s.stencil_func = CompareFunc(stencil_.func - GL_NEVER);
  s.stencil_ref = clamp_ref(stencil_.ref, stencil_bits_);
  s.stencil_value_mask = uint8_t(stencil_.value_mask);
  s.stencil_write_mask = uint8_t(stencil_.write_mask);
  s.stencil_fail = stencil_op_of(stencil_.fail);
  s.stencil_depth_fail = stencil_op_of(stencil_.depth_fail);
  s.stencil_pass = stencil_op_of(stencil_.pass);
}

bool Context::get_stencil(GLenum pname, std::vector<double>& out) const {
  // The masks read back within the buffer's bits, as Mesa answers them.
  const GLuint bits = stencil_bits_ ? 0xffu : 0u;
  switch (pname) {
    case GL_STENCIL_BITS: out = {double(stencil_bits_)}; return true;
    case GL_STENCIL_FUNC: out = {double(stencil_.func)}; return true;
    case GL_STENCIL_REF: out = {double(clamp_ref(stencil_.ref, stencil_bits_))}; return true;
    case GL_STENCIL_VALUE_MASK: out = {double(stencil_.value_mask & bits)}; return true;
    case GL_STENCIL_WRITEMASK: out = {double(stencil_.write_mask & bits)}; return true;
    case GL_STENCIL_FAIL: out = {double(stencil_.fail)}; return true;
    case GL_STENCIL_PASS_DEPTH_FAIL: out = {double(stencil_.depth_fail)}; return true;
    case GL_STENCIL_PASS_DEPTH_PASS: out = {double(stencil_.pass)}; return true;
    case GL_STENCIL_CLEAR_VALUE: out = {double(stencil_.clear)}; return true;
    default: return false;
  }
}

}  // namespace velocity::gl
