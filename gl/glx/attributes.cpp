// GLX attribute lists and configurations (attributes.hpp).
#include "attributes.hpp"

#include <GL/glx.h>
#include <GL/glxext.h>

#include <algorithm>
#include <tuple>
#include <utility>

namespace velocity::glx {

const Config kConfigs[kConfigCount] = {{1, true, 24, 8, 16}, {2, false, 24, 8, 16}, {3, true, 0, 0, 0}, {4, false, 0, 0, 0},
                                       // multisample (GLX_ARB_multisample): 4, 9 and 16 samples
                                       {5, true, 24, 8, 16, 2}, {6, false, 24, 8, 16, 2}, {7, true, 24, 8, 16, 3},
                                       {8, false, 24, 8, 16, 3}, {9, true, 24, 8, 16, 4}, {10, false, 24, 8, 16, 4}};

namespace {
constexpr int kDontCare = int(GLX_DONT_CARE);

// The attributes both lists share, each a minimum or an exact value.
bool sized_attribute(int a, Wanted& w, int value) {
  switch (a) {
    case GLX_RED_SIZE: w.colour[0] = value; return true;
    case GLX_GREEN_SIZE: w.colour[1] = value; return true;
    case GLX_BLUE_SIZE: w.colour[2] = value; return true;
    case GLX_ALPHA_SIZE: w.colour[3] = value; return true;
    case GLX_DEPTH_SIZE: w.depth = value; return true;
    case GLX_STENCIL_SIZE: w.stencil = value; return true;
    case GLX_ACCUM_RED_SIZE: w.accum[0] = value; return true;
    case GLX_ACCUM_GREEN_SIZE: w.accum[1] = value; return true;
    case GLX_ACCUM_BLUE_SIZE: w.accum[2] = value; return true;
    case GLX_ACCUM_ALPHA_SIZE: w.accum[3] = value; return true;
    case GLX_AUX_BUFFERS: w.aux = value; return true;
    case GLX_SAMPLES: w.samples = value; return true;
    case GLX_SAMPLE_BUFFERS: w.sample_buffers = value; return true;
    case GLX_BUFFER_SIZE: return true;  // colour index only
    case GLX_LEVEL: w.level = value; return true;
    default: return false;
  }
}
}  // namespace

bool parse_fbconfig_attributes(const int* list, int limit, Wanted& w) {
  w = Wanted{};
  for (int i = 0; list && i + 1 < limit && list[i] != None; i += 2) {
    const int v = list[i + 1];
    switch (list[i]) {
      case GLX_DOUBLEBUFFER: w.double_buffer = v; break;
      case GLX_STEREO: w.stereo = v; break;
      case GLX_RENDER_TYPE: w.render_type = v; break;
      case GLX_DRAWABLE_TYPE: w.drawable_type = v; break;
      case GLX_FBCONFIG_ID: w.id = v; break;
      case GLX_X_RENDERABLE: w.x_renderable = v; break;
      case GLX_X_VISUAL_TYPE: w.visual_type = v; break;
      case GLX_CONFIG_CAVEAT: w.caveat = v; break;
      case GLX_TRANSPARENT_TYPE: w.transparent = v; break;
      case GLX_TRANSPARENT_INDEX_VALUE: case GLX_TRANSPARENT_RED_VALUE: case GLX_TRANSPARENT_GREEN_VALUE:
      case GLX_TRANSPARENT_BLUE_VALUE: case GLX_TRANSPARENT_ALPHA_VALUE:
        break;  // only with a transparent type, which no configuration has
      default:
        if (!sized_attribute(list[i], w, v)) return false;
    }
  }
  return true;
}

// GLX 1.2's list: booleans stand alone; GLX_RGBA and GLX_DOUBLEBUFFER are required
// where wanted (absent: colour index, single-buffered).
bool parse_visual_attributes(const int* list, int limit, Wanted& w) {
  w = Wanted{};
  w.rgba = false, w.double_buffer = 0;
  for (int i = 0; list && i < limit && list[i] != None;) {
    const int name = list[i++];
    if (name == GLX_USE_GL) continue;
    if (name == GLX_RGBA) { w.rgba = true; continue; }
    if (name == GLX_DOUBLEBUFFER) { w.double_buffer = 1; continue; }
    if (name == GLX_STEREO) { w.stereo = 1; continue; }
    if (i >= limit || !sized_attribute(name, w, list[i])) return false;
    ++i;
  }
  return true;
}

bool config_attribute(const Config& c, unsigned long visual, int attribute, int* value) {
  int v = 0;
  switch (attribute) {
    case GLX_USE_GL: case GLX_RGBA: v = 1; break;
    case GLX_FBCONFIG_ID: v = c.id; break;
    case GLX_BUFFER_SIZE: v = 32; break;
    case GLX_STENCIL_SIZE: v = c.stencil; break;
    case GLX_ACCUM_RED_SIZE: case GLX_ACCUM_GREEN_SIZE: case GLX_ACCUM_BLUE_SIZE: case GLX_ACCUM_ALPHA_SIZE:
      v = c.accum; break;
    case GLX_SAMPLE_BUFFERS: v = c.samples() > 0; break;
    case GLX_SAMPLES: v = c.samples(); break;
    case GLX_LEVEL: case GLX_STEREO: case GLX_AUX_BUFFERS:
    case GLX_TRANSPARENT_INDEX_VALUE: case GLX_TRANSPARENT_RED_VALUE: case GLX_TRANSPARENT_GREEN_VALUE:
    case GLX_TRANSPARENT_BLUE_VALUE: case GLX_TRANSPARENT_ALPHA_VALUE:
      v = 0; break;
    case GLX_DOUBLEBUFFER: v = c.double_buffer; break;
    case GLX_RED_SIZE: case GLX_GREEN_SIZE: case GLX_BLUE_SIZE: case GLX_ALPHA_SIZE: v = 8; break;
    case GLX_DEPTH_SIZE: v = c.depth; break;
    case GLX_RENDER_TYPE: v = GLX_RGBA_BIT; break;
    case GLX_DRAWABLE_TYPE: v = visual ? GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT : GLX_PBUFFER_BIT; break;
    case GLX_X_RENDERABLE: v = visual != 0; break;
    case GLX_VISUAL_ID: v = int(visual); break;
    case GLX_X_VISUAL_TYPE: v = visual ? GLX_TRUE_COLOR : GLX_NONE; break;
    case GLX_CONFIG_CAVEAT: case GLX_TRANSPARENT_TYPE: v = GLX_NONE; break;
    case GLX_MAX_PBUFFER_WIDTH: case GLX_MAX_PBUFFER_HEIGHT: v = kMaxSize; break;
    case GLX_MAX_PBUFFER_PIXELS: v = kMaxSize * kMaxSize; break;
    default: return false;
  }
  *value = v;
  return true;
}

bool satisfies(int i, int visuals, const Wanted& w) {
  const Config& c = kConfigs[i];
  const bool visual = i < visuals;
  if (!w.rgba) return false;
  if (w.id != kDontCare) return w.id == c.id;
  if (w.double_buffer != kDontCare && bool(w.double_buffer) != c.double_buffer) return false;
  if (w.stereo != kDontCare && w.stereo) return false;
  if (w.level != 0) return false;
  for (int b : w.colour)
    if (b != kDontCare && b > 8) return false;
  if (w.depth != kDontCare && w.depth > c.depth) return false;
  if (w.stencil != kDontCare && w.stencil > c.stencil) return false;
  for (int v : w.accum)
    if (v != kDontCare && v > c.accum) return false;
  if (w.aux != kDontCare && w.aux > 0) return false;
  // Minimums: GLX_SAMPLES N is met by the configurations with N samples or more.
  if (w.sample_buffers != kDontCare && w.sample_buffers > (c.samples() > 0 ? 1 : 0)) return false;
  if (w.samples != kDontCare && w.samples > c.samples()) return false;
  if (w.render_type != kDontCare && !(w.render_type & GLX_RGBA_BIT)) return false;
  int drawable_types = 0;
  config_attribute(c, visual ? 1 : 0, GLX_DRAWABLE_TYPE, &drawable_types);
  if (w.drawable_type != kDontCare && (w.drawable_type & drawable_types) != w.drawable_type) return false;
  if (w.x_renderable != kDontCare && bool(w.x_renderable) != visual) return false;
  if (w.visual_type != kDontCare && w.visual_type != (visual ? GLX_TRUE_COLOR : GLX_NONE)) return false;
  if (w.caveat != kDontCare && w.caveat != GLX_NONE) return false;
  if (w.transparent != kDontCare && w.transparent != GLX_NONE) return false;
  return true;
}

std::vector<const Config*> choose_fbconfigs(const Wanted& w, int visuals) {
  std::vector<const Config*> found;
  for (int i = 0; i < kConfigCount; ++i)
    if (satisfies(i, visuals, w)) found.push_back(&kConfigs[i]);
  // GLX 1.4's order: single before double buffered, then the fewer samples, then the
  // smaller depth buffer, then the smaller stencil buffer.
  std::stable_sort(found.begin(), found.end(), [](const Config* a, const Config* b) {
    return std::make_tuple(a->double_buffer, a->samples(), a->depth, a->stencil) <
           std::make_tuple(b->double_buffer, b->samples(), b->depth, b->stencil);
  });
  return found;
}

const Config* choose_visual(const Wanted& w, int visuals) {
  // Of those that qualify: the fewest samples (GLX_SAMPLES is met by the smallest
  // count that reaches it), then no depth buffer if none was asked for, else the deepest.
  const Config* best = nullptr;
  for (int i = 0; i < kConfigCount && i < visuals; ++i) {
    const Config& c = kConfigs[i];
    if (!satisfies(i, visuals, w)) continue;
    if (!best || c.samples() < best->samples() ||
        (c.samples() == best->samples() && (w.depth == 0 ? c.depth < best->depth : c.depth > best->depth)))
      best = &c;
  }
  return best;
}

ContextError check_context_attributes(const int* list, int limit) {
  int major = 1, minor = 0, flags = 0, profile = GLX_CONTEXT_CORE_PROFILE_BIT_ARB, render_type = GLX_RGBA_TYPE;
  for (int i = 0; list && i + 1 < limit && list[i] != None; i += 2) {
    const int v = list[i + 1];
    switch (list[i]) {
      case GLX_CONTEXT_MAJOR_VERSION_ARB: major = v; break;
      case GLX_CONTEXT_MINOR_VERSION_ARB: minor = v; break;
      case GLX_CONTEXT_FLAGS_ARB: flags = v; break;
      case GLX_CONTEXT_PROFILE_MASK_ARB: profile = v; break;
      case GLX_RENDER_TYPE: render_type = v; break;
      default: return ContextError::WrongValue;
    }
  }
  if ((flags & ~(GLX_CONTEXT_DEBUG_BIT_ARB | GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB)) || render_type != GLX_RGBA_TYPE)
    return ContextError::WrongValue;
  const bool profiles = major > 3 || (major == 3 && minor >= 2);
  if (profiles && profile != GLX_CONTEXT_CORE_PROFILE_BIT_ARB && profile != GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB)
    return ContextError::WrongProfile;
  // Only what pGL is: OpenGL 1.0 to 1.5 (a forward-compatible context needs 3.0).
  if (major != 1 || minor < 0 || minor > 5 || (flags & GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB))
    return ContextError::Unsupported;
  return ContextError::Ok;
}

PbufferError parse_pbuffer_attributes(const int* list, int limit, PbufferSize& size) {
  size = PbufferSize{};
  bool largest = false;
  for (int i = 0; list && i + 1 < limit && list[i] != None; i += 2) {
    const int v = list[i + 1];
    switch (list[i]) {
      case GLX_PBUFFER_WIDTH: size.width = v; break;
      case GLX_PBUFFER_HEIGHT: size.height = v; break;
      case GLX_LARGEST_PBUFFER: largest = v != 0; break;
      case GLX_PRESERVED_CONTENTS: break;  // always preserved
      default: return PbufferError::WrongValue;
    }
  }
  if (size.width < 0 || size.height < 0) return PbufferError::WrongValue;
  if (size.width > kMaxSize || size.height > kMaxSize) {
    if (!largest) return PbufferError::TooLarge;
    size.width = std::min(size.width, kMaxSize), size.height = std::min(size.height, kMaxSize);
  }
  return PbufferError::Ok;
}

}  // namespace velocity::glx
