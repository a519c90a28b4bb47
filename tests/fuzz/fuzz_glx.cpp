// Fuzz target: the GLX vendor's attribute lists (gl/glx/attributes.hpp), the input a
// program hands glXChooseFBConfig, glXChooseVisual, glXCreateContextAttribsARB and
// glXCreatePbuffer. The bytes become an int list (sometimes with no None at its end:
// the parsers must stop at their limit) and a count of X visuals (0..6).
//
// Properties: no sanitizer report; every configuration chosen qualifies, and comes in
// GLX's order (single before double buffered, then the smaller depth buffer); what is
// chosen has no stencil or accumulation buffer; glXChooseVisual's choice has a visual;
// a context is only accepted for OpenGL 1.0-1.4; a pbuffer's size is within bounds.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "attributes.hpp"
#include "fuzz_util.hpp"

namespace glx = velocity::glx;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const int visuals = data[0] % 7;
  const bool terminated = data[1] & 1;
  std::vector<int> list;
  // Attribute names drawn near GLX's (0x1..0x30, 0x8000.., 0x2090..) and any value.
  for (size_t i = 2; i + 4 <= size && list.size() < 256; i += 4) {
    int v;
    std::memcpy(&v, data + i, 4);
    if ((list.size() & 1) == 0) {
      static const int bases[] = {0, 0x8000, 0x2090, 0x9120, 0x20f0, 0x100000};
      v = bases[(unsigned(v) >> 8) % 6] + int(unsigned(v) & 0x3f);
      if ((unsigned(v) & 0xff) == 0x3f) v = 0;  // None, now and then
    }
    list.push_back(v);
  }
  if (terminated || list.empty()) list.push_back(0);
  const int n = int(list.size());

  glx::Wanted w;
  if (glx::parse_fbconfig_attributes(list.data(), n, w)) {
    const std::vector<const glx::Config*> found = glx::choose_fbconfigs(w, visuals);
    for (size_t i = 0; i < found.size(); ++i) {
      const int index = int(found[i] - glx::kConfigs);
      fuzz_check(index >= 0 && index < glx::kConfigCount && glx::satisfies(index, visuals, w));
      if (i > 0)
        fuzz_check(found[i - 1]->double_buffer < found[i]->double_buffer ||
                (found[i - 1]->double_buffer == found[i]->double_buffer && found[i - 1]->depth <= found[i]->depth));
      int stencil = -1, accum = -1;
      // An 8-bit stencil buffer and a 16-bit accumulation buffer with the depth buffer,
      // or none of them; at least what was asked (unless a configuration was asked for by
      // its id, which overrides the rest).
      fuzz_check(glx::config_attribute(*found[i], 0, 0x0D /*GLX_STENCIL_SIZE*/, &stencil) &&
                 stencil == (found[i]->depth ? 8 : 0) && (w.id != -1 || w.stencil == -1 || stencil >= w.stencil));
      fuzz_check(glx::config_attribute(*found[i], 0, 0x0E /*GLX_ACCUM_RED_SIZE*/, &accum) &&
                 accum == (found[i]->depth ? 16 : 0) && (w.id != -1 || w.accum[0] == -1 || accum >= w.accum[0]));
    }
  }
  if (glx::parse_visual_attributes(list.data(), n, w)) {
    if (const glx::Config* c = glx::choose_visual(w, visuals)) fuzz_check(int(c - glx::kConfigs) < visuals);
  }
  const glx::ContextError e = glx::check_context_attributes(list.data(), n);
  (void)e;
  glx::PbufferSize pb;
  if (glx::parse_pbuffer_attributes(list.data(), n, pb) == glx::PbufferError::Ok)
    fuzz_check(pb.width >= 0 && pb.height >= 0 && pb.width <= glx::kMaxSize && pb.height <= glx::kMaxSize);
  for (const glx::Config& c : glx::kConfigs)
    for (int a = 0; a < 0x30; ++a) {
      int value;
      glx::config_attribute(c, unsigned(visuals), a, &value);
      glx::config_attribute(c, 0, 0x8000 + a, &value);
    }
  return 0;
}
