// The EGL vendor's configurations and the attribute lists programs pass it
// (eglChooseConfig, eglCreateContext, eglCreatePbufferSurface): parsed and matched here,
// apart from the vendor's objects, by the rules of the EGL 1.5 specification (section
// 3.4: the matching criteria, defaults and sort order of Table 3.4), with EGL's error
// codes. No libEGL calls: the fuzzer (tests/fuzz/fuzz_egl.cpp) drives the vendor whole.
#pragma once

#include <EGL/egl.h>

#include <vector>

namespace velocity::egl {

// What exists: 8-bit red, green, blue and alpha (pGL's colour buffer), a 24-bit depth
// buffer with an 8-bit stencil buffer or neither, and multisample configurations of
// k x k samples a pixel (k = 2, 3, 4: EGL_SAMPLES 4, 9, 16; pGL's super-sampling,
// gl/src/multisample.cpp). Pbuffers only (no native windows or pixmaps: the platforms
// served are headless), desktop OpenGL only.
struct Config {
  EGLint id;
  int depth;
  int stencil;
  int samples_side;  // k (1: no multisample buffer)
  int samples() const { return samples_side > 1 ? samples_side * samples_side : 0; }
};
constexpr int kConfigCount = 5;
extern const Config kConfigs[kConfigCount];
constexpr int kMaxSize = 16384;  // the largest pbuffer side (velocity::gl::kMaxViewport)
constexpr int kListLimit = 4096;  // ints read of a program's attribute list, at most

// One attribute of a configuration (eglGetConfigAttrib). False: not an attribute.
bool config_attribute(const Config& c, EGLint attribute, EGLint* value);

// eglChooseConfig: the configurations that match `list` (EGL_NONE-terminated, null
// for none), best first by Table 3.4's sort order; or EGL_BAD_ATTRIBUTE in `error` for
// an attribute or value that is not EGL's.
std::vector<const Config*> choose_configs(const EGLint* list, int limit, EGLint* error);

// eglCreateContext's list (EGL 1.5 / EGL_KHR_create_context): what pGL gives, an
// OpenGL 1.0-1.5 compatibility context, or the error (EGL_BAD_ATTRIBUTE, EGL_BAD_MATCH).
struct ContextRequest {
  int major = 1, minor = 0;
};
EGLint check_context_attributes(const EGLint* list, int limit, ContextRequest* request);

// eglCreatePbufferSurface's list: the size (clamped to kMaxSize with
// EGL_LARGEST_PBUFFER), or the error (EGL_BAD_ATTRIBUTE, EGL_BAD_PARAMETER, EGL_BAD_MATCH,
// EGL_BAD_ALLOC for a size beyond kMaxSize).
struct PbufferRequest {
  int width = 0, height = 0;
  bool largest = false;
};
EGLint parse_pbuffer_attributes(const EGLint* list, int limit, PbufferRequest* request);

}  // namespace velocity::egl
