#include "configs.hpp"

#include <EGL/eglext.h>

#include <algorithm>
#include <tuple>

namespace velocity::egl {

// EGL_CONFIG_ID order: the usual ones first. Every one has pGL's RGBA8888 colour buffer.
const Config kConfigs[kConfigCount] = {
    {1, 24, 8, 1}, {2, 0, 0, 1}, {3, 24, 8, 2}, {4, 24, 8, 3}, {5, 24, 8, 4},
};

bool config_attribute(const Config& c, EGLint attribute, EGLint* value) {
  switch (attribute) {
    case EGL_BUFFER_SIZE: *value = 32; return true;
    case EGL_RED_SIZE: case EGL_GREEN_SIZE: case EGL_BLUE_SIZE: case EGL_ALPHA_SIZE: *value = 8; return true;
    case EGL_LUMINANCE_SIZE: case EGL_ALPHA_MASK_SIZE: *value = 0; return true;
    case EGL_COLOR_BUFFER_TYPE: *value = EGL_RGB_BUFFER; return true;
    case EGL_DEPTH_SIZE: *value = c.depth; return true;
    case EGL_STENCIL_SIZE: *value = c.stencil; return true;
    case EGL_SAMPLE_BUFFERS: *value = c.samples() ? 1 : 0; return true;
    case EGL_SAMPLES: *value = c.samples(); return true;
    case EGL_CONFIG_ID: *value = c.id; return true;
    case EGL_CONFIG_CAVEAT: *value = EGL_NONE; return true;
    case EGL_CONFORMANT: case EGL_RENDERABLE_TYPE: *value = EGL_OPENGL_BIT; return true;
    // A pbuffer is never swapped: what it holds stays (eglSurfaceAttrib's
    // EGL_BUFFER_PRESERVED is honoured, which needs the bit).
    case EGL_SURFACE_TYPE: *value = EGL_PBUFFER_BIT | EGL_SWAP_BEHAVIOR_PRESERVED_BIT; return true;
    case EGL_LEVEL: *value = 0; return true;
    case EGL_MAX_PBUFFER_WIDTH: case EGL_MAX_PBUFFER_HEIGHT: *value = kMaxSize; return true;
    case EGL_MAX_PBUFFER_PIXELS: *value = kMaxSize * kMaxSize; return true;
    // Nothing waits for a display's refresh: a pbuffer's eglSwapBuffers does nothing.
    case EGL_MIN_SWAP_INTERVAL: case EGL_MAX_SWAP_INTERVAL: *value = 0; return true;
    case EGL_NATIVE_RENDERABLE: case EGL_BIND_TO_TEXTURE_RGB: case EGL_BIND_TO_TEXTURE_RGBA: *value = EGL_FALSE; return true;
    case EGL_NATIVE_VISUAL_ID: *value = 0; return true;
    case EGL_NATIVE_VISUAL_TYPE: case EGL_TRANSPARENT_TYPE: *value = EGL_NONE; return true;
    case EGL_TRANSPARENT_RED_VALUE: case EGL_TRANSPARENT_GREEN_VALUE: case EGL_TRANSPARENT_BLUE_VALUE: *value = 0; return true;
    default: return false;
  }
}

namespace {

// How an attribute of eglChooseConfig's list is matched (Table 3.4).
enum class Match { AtLeast, Exact, Mask, Ignored };

struct Criterion {
  EGLint attribute;
  Match match;
  EGLint fallback;  // the default when the list does not name it
};

constexpr Criterion kCriteria[] = {
    {EGL_BUFFER_SIZE, Match::AtLeast, 0},
    {EGL_RED_SIZE, Match::AtLeast, 0},
    {EGL_GREEN_SIZE, Match::AtLeast, 0},
    {EGL_BLUE_SIZE, Match::AtLeast, 0},
    {EGL_LUMINANCE_SIZE, Match::AtLeast, 0},
    {EGL_ALPHA_SIZE, Match::AtLeast, 0},
    {EGL_ALPHA_MASK_SIZE, Match::AtLeast, 0},
    {EGL_BIND_TO_TEXTURE_RGB, Match::Exact, EGL_DONT_CARE},
    {EGL_BIND_TO_TEXTURE_RGBA, Match::Exact, EGL_DONT_CARE},
    {EGL_COLOR_BUFFER_TYPE, Match::Exact, EGL_RGB_BUFFER},
    {EGL_CONFIG_CAVEAT, Match::Exact, EGL_DONT_CARE},
    {EGL_CONFIG_ID, Match::Exact, EGL_DONT_CARE},
    {EGL_CONFORMANT, Match::Mask, 0},
    {EGL_DEPTH_SIZE, Match::AtLeast, 0},
    {EGL_LEVEL, Match::Exact, 0},
    {EGL_MAX_SWAP_INTERVAL, Match::Exact, EGL_DONT_CARE},
    {EGL_MIN_SWAP_INTERVAL, Match::Exact, EGL_DONT_CARE},
    {EGL_NATIVE_RENDERABLE, Match::Exact, EGL_DONT_CARE},
    {EGL_NATIVE_VISUAL_TYPE, Match::Exact, EGL_DONT_CARE},
    {EGL_RENDERABLE_TYPE, Match::Mask, EGL_OPENGL_ES_BIT},
    {EGL_SAMPLE_BUFFERS, Match::AtLeast, 0},
    {EGL_SAMPLES, Match::AtLeast, 0},
    {EGL_STENCIL_SIZE, Match::AtLeast, 0},
    {EGL_SURFACE_TYPE, Match::Mask, EGL_WINDOW_BIT},
    {EGL_TRANSPARENT_TYPE, Match::Exact, EGL_NONE},
    {EGL_TRANSPARENT_RED_VALUE, Match::Exact, EGL_DONT_CARE},
    {EGL_TRANSPARENT_GREEN_VALUE, Match::Exact, EGL_DONT_CARE},
    {EGL_TRANSPARENT_BLUE_VALUE, Match::Exact, EGL_DONT_CARE},
    // "ignored": the pbuffer limits and the visual id are not selection criteria.
    {EGL_MAX_PBUFFER_WIDTH, Match::Ignored, EGL_DONT_CARE},
    {EGL_MAX_PBUFFER_HEIGHT, Match::Ignored, EGL_DONT_CARE},
    {EGL_MAX_PBUFFER_PIXELS, Match::Ignored, EGL_DONT_CARE},
    {EGL_NATIVE_VISUAL_ID, Match::Ignored, EGL_DONT_CARE},
};
constexpr int kCriterionCount = int(sizeof kCriteria / sizeof kCriteria[0]);

int criterion_of(EGLint attribute) {
  for (int i = 0; i < kCriterionCount; ++i)
    if (kCriteria[i].attribute == attribute) return i;
  return -1;
}

// Whether `value` is one EGL defines for the attribute (EGL_DONT_CARE is, except for
// EGL_LEVEL).
bool valid_value(EGLint attribute, EGLint value) {
  if (value == EGL_DONT_CARE) return attribute != EGL_LEVEL;
  switch (attribute) {
    case EGL_BIND_TO_TEXTURE_RGB: case EGL_BIND_TO_TEXTURE_RGBA: case EGL_NATIVE_RENDERABLE:
      return value == EGL_TRUE || value == EGL_FALSE;
    case EGL_COLOR_BUFFER_TYPE: return value == EGL_RGB_BUFFER || value == EGL_LUMINANCE_BUFFER;
    case EGL_CONFIG_CAVEAT: return value == EGL_NONE || value == EGL_SLOW_CONFIG || value == EGL_NON_CONFORMANT_CONFIG;
    case EGL_TRANSPARENT_TYPE: return value == EGL_NONE || value == EGL_TRANSPARENT_RGB;
    case EGL_CONFORMANT: case EGL_RENDERABLE_TYPE: case EGL_SURFACE_TYPE: case EGL_CONFIG_ID: case EGL_LEVEL:
    case EGL_NATIVE_VISUAL_TYPE: case EGL_MAX_PBUFFER_WIDTH: case EGL_MAX_PBUFFER_HEIGHT:
    case EGL_MAX_PBUFFER_PIXELS: case EGL_NATIVE_VISUAL_ID:
      return true;
    default: return value >= 0;  // sizes, counts, swap intervals, transparent values
  }
}

}  // namespace

std::vector<const Config*> choose_configs(const EGLint* list, int limit, EGLint* error) {
  *error = EGL_SUCCESS;
  EGLint wanted[kCriterionCount];
  for (int i = 0; i < kCriterionCount; ++i) wanted[i] = kCriteria[i].fallback;
  bool native_pixmap = false;
  for (int i = 0; list && i + 1 < limit && list[i] != EGL_NONE; i += 2) {
    const EGLint attribute = list[i], value = list[i + 1];
    if (attribute == EGL_MATCH_NATIVE_PIXMAP) {  // the headless platforms have no pixmaps
      native_pixmap = value != EGL_NONE;
      continue;
    }
    const int k = criterion_of(attribute);
    if (k < 0 || !valid_value(attribute, value)) {
      *error = EGL_BAD_ATTRIBUTE;
      return {};
    }
    wanted[k] = value;
  }
  std::vector<const Config*> found;
  if (native_pixmap) return found;
  const EGLint id = wanted[criterion_of(EGL_CONFIG_ID)];
  for (const Config& c : kConfigs) {
    if (id != EGL_DONT_CARE) {  // "all other attributes are ignored"
      if (c.id == id) found.push_back(&c);
      continue;
    }
    bool ok = true;
    for (int k = 0; k < kCriterionCount && ok; ++k) {
      const Criterion& criterion = kCriteria[k];
      const EGLint w = wanted[k];
      if (w == EGL_DONT_CARE || criterion.match == Match::Ignored) continue;
      // The transparent colour counts only for a transparent configuration (none is).
      if ((criterion.attribute == EGL_TRANSPARENT_RED_VALUE || criterion.attribute == EGL_TRANSPARENT_GREEN_VALUE ||
           criterion.attribute == EGL_TRANSPARENT_BLUE_VALUE) &&
          wanted[criterion_of(EGL_TRANSPARENT_TYPE)] != EGL_TRANSPARENT_RGB)
        continue;
      EGLint have = 0;
      config_attribute(c, criterion.attribute, &have);
      switch (criterion.match) {
        case Match::AtLeast: ok = have >= w; break;
        case Match::Exact: ok = have == w; break;
        case Match::Mask: ok = (have & w) == w; break;
        case Match::Ignored: break;
      }
    }
    if (ok) found.push_back(&c);
  }
  // Section 3.4.1.2's order, of what differs between these configurations: the fewer
  // sample buffers and samples, the smaller depth and stencil buffers, then the id.
  // (Caveat, buffer type, colour bits and buffer size are the same in all.)
  std::sort(found.begin(), found.end(), [](const Config* a, const Config* b) {
    return std::make_tuple(a->samples() ? 1 : 0, a->samples(), a->depth, a->stencil, a->id) <
           std::make_tuple(b->samples() ? 1 : 0, b->samples(), b->depth, b->stencil, b->id);
  });
  return found;
}

EGLint check_context_attributes(const EGLint* list, int limit, ContextRequest* request) {
  *request = ContextRequest{};
  EGLint flags = 0;
  bool forward = false, robust = false;
  for (int i = 0; list && i + 1 < limit && list[i] != EGL_NONE; i += 2) {
    const EGLint v = list[i + 1];
    switch (list[i]) {
      case EGL_CONTEXT_MAJOR_VERSION: request->major = v; break;  // (= EGL_CONTEXT_CLIENT_VERSION)
      case EGL_CONTEXT_MINOR_VERSION: request->minor = v; break;
      case EGL_CONTEXT_FLAGS_KHR: flags = v; break;
      // Below OpenGL 3.2 the profile is ignored (EGL_KHR_create_context): every one is.
      case EGL_CONTEXT_OPENGL_PROFILE_MASK: break;
      case EGL_CONTEXT_OPENGL_DEBUG:
      case EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE:
      case EGL_CONTEXT_OPENGL_ROBUST_ACCESS:
        if (v != EGL_TRUE && v != EGL_FALSE) return EGL_BAD_ATTRIBUTE;
        if (list[i] == EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE) forward = v == EGL_TRUE;
        if (list[i] == EGL_CONTEXT_OPENGL_ROBUST_ACCESS) robust = v == EGL_TRUE;
        break;
      case EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY:
        if (v == EGL_LOSE_CONTEXT_ON_RESET) return EGL_BAD_MATCH;  // pGL's contexts are never lost
        if (v != EGL_NO_RESET_NOTIFICATION) return EGL_BAD_ATTRIBUTE;
        break;
      default: return EGL_BAD_ATTRIBUTE;
    }
  }
  if (flags & ~(EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR | EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR |
                EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR))
    return EGL_BAD_ATTRIBUTE;
  forward = forward || (flags & EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR);
  robust = robust || (flags & EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR);
  // Only what pGL is: OpenGL 1.0 to 1.5, without robust buffer access (a forward-
  // compatible context needs 3.0). Versions that do not exist and later ones alike.
  if (request->major != 1 || request->minor < 0 || request->minor > 5 || forward || robust) return EGL_BAD_MATCH;
  return EGL_SUCCESS;
}

EGLint parse_pbuffer_attributes(const EGLint* list, int limit, PbufferRequest* request) {
  *request = PbufferRequest{};
  EGLint texture_format = EGL_NO_TEXTURE, texture_target = EGL_NO_TEXTURE;
  for (int i = 0; list && i + 1 < limit && list[i] != EGL_NONE; i += 2) {
    const EGLint v = list[i + 1];
    switch (list[i]) {
      case EGL_WIDTH: request->width = v; break;
      case EGL_HEIGHT: request->height = v; break;
      case EGL_LARGEST_PBUFFER: request->largest = v != EGL_FALSE; break;
      case EGL_TEXTURE_FORMAT:
        if (v != EGL_NO_TEXTURE && v != EGL_TEXTURE_RGB && v != EGL_TEXTURE_RGBA) return EGL_BAD_ATTRIBUTE;
        texture_format = v;
        break;
      case EGL_TEXTURE_TARGET:
        if (v != EGL_NO_TEXTURE && v != EGL_TEXTURE_2D) return EGL_BAD_ATTRIBUTE;
        texture_target = v;
        break;
      case EGL_MIPMAP_TEXTURE: break;  // (only for a texture format, which none has)
      case EGL_VG_COLORSPACE:
        if (v != EGL_VG_COLORSPACE_sRGB && v != EGL_VG_COLORSPACE_LINEAR) return EGL_BAD_ATTRIBUTE;
        break;
      case EGL_VG_ALPHA_FORMAT:
        if (v != EGL_VG_ALPHA_FORMAT_NONPRE && v != EGL_VG_ALPHA_FORMAT_PRE) return EGL_BAD_ATTRIBUTE;
        break;
      default: return EGL_BAD_ATTRIBUTE;
    }
  }
  // No configuration binds to a texture (EGL_BIND_TO_TEXTURE_RGB/RGBA are false).
  if (texture_format != EGL_NO_TEXTURE || texture_target != EGL_NO_TEXTURE) return EGL_BAD_MATCH;
  if (request->width < 0 || request->height < 0) return EGL_BAD_PARAMETER;
  if (request->width > kMaxSize || request->height > kMaxSize) {
    if (!request->largest) return EGL_BAD_ALLOC;
    request->width = std::min(request->width, kMaxSize), request->height = std::min(request->height, kMaxSize);
  }
  return EGL_SUCCESS;
}

}  // namespace velocity::egl
