// libvelocity-gpu's one exported symbol: make_backend (src/backend_choice.cpp) finds it
// by name after dlopen. Nothing thrown crosses it: errors come back as a message.
#include <cstdio>
#include <new>

#include "gpu_backend.hpp"
#include "velocity/error.hpp"

extern "C" __attribute__((visibility("default"))) velocity::Backend* velocity_gpu_make_backend(
    unsigned long abi, int width, int height, int hardware_only, char* message, size_t message_size,
    velocity::GlContextProvider* window) {
  auto say = [&](const std::string& s) { std::snprintf(message, message_size, "%s", s.c_str()); };
  if (abi != velocity::kGpuBackendAbi) {
    say("libvelocity-gpu was built from other headers than this program (a mismatched install)");
    return nullptr;
  }
  try {
    auto* b = new velocity::gpu::GpuBackend(width, height, hardware_only != 0, window);
    say(b->description());
    return b;
  } catch (const std::exception& e) {
    say(e.what());
  } catch (...) {
    say("unknown error");
  }
  return nullptr;
}
