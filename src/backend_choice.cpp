// Choosing a Renderer's backend: the CPU pipeline, or the GPU backend from
// libvelocity-gpu. The core library never links OpenGL: the GPU library is loaded with
// dlopen the first time a renderer asks for it, and stays loaded (its backends'
// code must outlive them).
#include <dlfcn.h>

#include <cstdlib>
#include <mutex>
#include <string>
#include <vector>

#include "velocity/backend.hpp"
#include "velocity/error.hpp"

#ifndef VELOCITY_GPU_LIBRARY_DIRS
#define VELOCITY_GPU_LIBRARY_DIRS ""
#endif

namespace velocity {

const char* to_string(BackendChoice choice) {
  switch (choice) {
    case BackendChoice::Cpu: return "cpu";
    case BackendChoice::Gpu: return "gpu";
    case BackendChoice::Auto: return "auto";
  }
  return "?";
}

std::optional<BackendChoice> parse_backend(std::string_view name) {
  if (name == "cpu") return BackendChoice::Cpu;
  if (name == "gpu") return BackendChoice::Gpu;
  if (name == "auto") return BackendChoice::Auto;
  return std::nullopt;
}

namespace {

constexpr const char* kLibrary = "libvelocity-gpu.so";

// The library's entry point, or null with why in `error`. Loaded once per process.
GpuBackendEntry load_entry(std::string& error) {
  static std::once_flag once;
  static GpuBackendEntry entry = nullptr;
  static std::string load_error;
  std::call_once(once, [] {
    // Where to look: the environment's choice alone when set; else the dynamic linker's
    // path (an rpath, LD_LIBRARY_PATH, an installed copy), then the build tree and the
    // install's library folder (compiled in: VELOCITY_GPU_LIBRARY_DIRS).
    std::vector<std::string> candidates;
    if (const char* path = std::getenv("VELOCITY_GPU_LIBRARY"); path && *path) {
      candidates.push_back(path);
    } else {
      candidates.push_back(kLibrary);
      std::string dirs = VELOCITY_GPU_LIBRARY_DIRS;
      for (size_t at = 0; at < dirs.size();) {
        size_t end = dirs.find(':', at);
        if (end == std::string::npos) end = dirs.size();
        if (end > at) candidates.push_back(dirs.substr(at, end - at) + "/" + kLibrary);
        at = end + 1;
      }
    }
    std::string tried;
    for (const std::string& c : candidates) {
      void* handle = dlopen(c.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) {
        const char* e = dlerror();
        if (tried.empty()) tried = e ? e : c + ": not loadable";  // the first says most (the linker's search)
        continue;
      }
      void* symbol = dlsym(handle, kGpuBackendEntry);
      if (!symbol) {
        load_error = c + " has no " + kGpuBackendEntry;
        return;
      }
      entry = reinterpret_cast<GpuBackendEntry>(symbol);
      return;
    }
    load_error = "libvelocity-gpu is not installed or not loadable (" + tried +
                 "); build it with libepoxy-dev and libegl-dev, or set VELOCITY_GPU_LIBRARY";
  });
  error = load_error;
  return entry;
}

}  // namespace

std::unique_ptr<Backend> make_backend(BackendChoice choice, int width, int height, BackendChoice& drawn_by,
                                      std::string& reason) {
  if (choice == BackendChoice::Cpu) {
    drawn_by = BackendChoice::Cpu, reason = "asked for";
    return make_cpu_backend(width, height);
  }
  const bool automatic = choice == BackendChoice::Auto;
  std::string error;
  if (GpuBackendEntry entry = load_entry(error)) {
    char message[512] = {};
    Backend* gpu = entry(kGpuBackendAbi, width, height, automatic ? 1 : 0, message, sizeof message, nullptr);
    if (gpu) {
      drawn_by = BackendChoice::Gpu;
      reason = std::string(automatic ? "auto: " : "asked for: ") + message;
      return std::unique_ptr<Backend>(gpu);
    }
    error = message;
  }
  if (!automatic) throw Error("the GPU backend is not available: " + error);
  drawn_by = BackendChoice::Cpu;
  reason = "auto: " + error;
  return make_cpu_backend(width, height);
}

std::unique_ptr<Backend> make_backend_on(GlContextProvider& window, int width, int height, bool hardware_only,
                                         std::string& reason) {
  std::string error;
  GpuBackendEntry entry = load_entry(error);
  if (!entry) throw Error("the GPU backend is not available: " + error);
  char message[512] = {};
  Backend* gpu = entry(kGpuBackendAbi, width, height, hardware_only ? 1 : 0, message, sizeof message, &window);
  if (!gpu) throw Error("the GPU backend cannot draw in the window: " + std::string(message));
  reason = std::string(hardware_only ? "auto: " : "asked for: ") + message;
  return std::unique_ptr<Backend>(gpu);
}

void Backend::present_window(int, int, const uint8_t*) {
  throw Error("present_window: this renderer was not made on a window's OpenGL context");
}

}  // namespace velocity
