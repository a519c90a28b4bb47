// The GLX vendor's configurations and the attribute lists programs pass it
// (glXChooseFBConfig, glXChooseVisual, glXCreateContextAttribsARB, glXCreatePbuffer):
// parsed and matched here without a display, so that the fuzzer (tests/fuzz/fuzz_glx.cpp)
// drives exactly the code glx.cpp runs.
#pragma once

#include <vector>

namespace velocity::glx {

// What exists: 8-bit red, green, blue and alpha, a 24-bit depth buffer with an 8-bit
// stencil buffer and a 16-bit accumulation buffer, or none of them, single or double
// buffered. No auxiliary buffers or stereo: pGL has none, so no configuration claims
// them. Configuration i is shown in the screen's i-th usable X visual; one without a
// visual is for pbuffers.
//
// Multisample configurations (GLX_ARB_multisample) have k x k samples a pixel, k = 2,
// 3 or 4 (GLX_SAMPLES 4, 9, 16: the renderer's super-sampling, gl/src/multisample.cpp),
// with depth, stencil and accumulation buffers.
struct Config {
  int id;
  bool double_buffer;
  int depth;
  int stencil;
  int accum;             // bits a component
  int samples_side = 1;  // k: k x k samples a pixel (1: no multisample buffer)
  int samples() const { return samples_side > 1 ? samples_side * samples_side : 0; }
};
constexpr int kConfigCount = 10;
extern const Config kConfigs[kConfigCount];
constexpr int kMaxSize = 16384;  // the largest drawable pGL renders (velocity::gl::kMaxViewport)
constexpr int kMaxSwapInterval = 1000;

// What glXChooseVisual / glXChooseFBConfig asked for (GLX_DONT_CARE is -1).
struct Wanted {
  int double_buffer = -1, stereo = 0, level = 0, colour[4] = {0, 0, 0, 0}, depth = 0, stencil = 0;
  int accum[4] = {0, 0, 0, 0}, aux = 0, samples = 0, sample_buffers = 0, render_type = 1 /*GLX_RGBA_BIT*/;
  int drawable_type = 1 /*GLX_WINDOW_BIT*/, id = -1, x_renderable = -1, visual_type = -1, caveat = -1;
  int transparent = 0x8000 /*GLX_NONE*/;
  bool rgba = true;  // glXChooseVisual: GLX_RGBA given (else colour index, which no visual is)
};

// None-terminated lists, read to at most `limit` ints. False: an unknown attribute.
bool parse_fbconfig_attributes(const int* list, int limit, Wanted& w);
bool parse_visual_attributes(const int* list, int limit, Wanted& w);

// Whether configuration i (which has an X visual when i < visuals) qualifies.
bool satisfies(int i, int visuals, const Wanted& w);
// glXChooseFBConfig: those that qualify, in GLX 1.4's order.
std::vector<const Config*> choose_fbconfigs(const Wanted& w, int visuals);
// glXChooseVisual: the best one with a visual, or null.
const Config* choose_visual(const Wanted& w, int visuals);

// One attribute of configuration c, shown in `visual` (0: none). False: unknown.
bool config_attribute(const Config& c, unsigned long visual, int attribute, int* value);

// glXCreateContextAttribsARB's list: what pGL can give (OpenGL 1.0 to 1.5), or why not.
enum class ContextError { Ok, WrongValue, Unsupported, WrongProfile };  // X errors: BadValue, BadMatch, GLXBadProfileARB
ContextError check_context_attributes(const int* list, int limit);

// glXCreatePbuffer's list.
enum class PbufferError { Ok, WrongValue, TooLarge };  // X errors: BadValue, BadAlloc
struct PbufferSize {
  int width = 0, height = 0;
};
PbufferError parse_pbuffer_attributes(const int* list, int limit, PbufferSize& size);

}  // namespace velocity::glx
