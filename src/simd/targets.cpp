#include "simd/targets.hpp"

#include <hwy/targets.h>

#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace velocity::simd {

namespace {

// HWY_TARGETS is what this file is compiled for; the kernels' files get the same
// definitions (VELOCITY_HWY_DEFINITIONS in src/CMakeLists.txt), so it is theirs too.
int64_t available_mask() { return hwy::SupportedTargets() & HWY_TARGETS; }

std::string apply(const char* request) {
  if (request == nullptr || *request == '\0') return {};
  const std::string error = std::string("VELOCITY_SIMD_TARGET=") + request +
                            ": not one of the targets this build and processor run (" + available_targets() + ")";
  for (int64_t rest = available_mask(); rest != 0; rest &= rest - 1) {
    const int64_t target = rest & -rest;
    if (std::string_view(hwy::TargetName(target)) != request) continue;
    // Highway's targets are bits, better ones lower: disabling every bit below the
    // requested one leaves it the best. The baseline cannot be disabled, so check.
    hwy::DisableTargets(target - 1);
    // Highway 1.0 chooses once, at the first dispatch (SupportedTargets() above counts
    // as one), and DisableTargets does not undo that choice: choose again.
    const int64_t chosen = hwy::SupportedTargets() & HWY_TARGETS;
    hwy::GetChosenTarget().Update(hwy::SupportedTargets());
    if ((chosen & -chosen) == target) return {};
    break;
  }
  return error;
}

}  // namespace

std::string available_targets() {
  std::string names;
  for (int64_t rest = available_mask(); rest != 0; rest &= rest - 1) {
    if (!names.empty()) names += ' ';
    names += hwy::TargetName(rest & -rest);
  }
  return names;
}

const std::string& apply_target_request() {
  static const std::string error = apply(std::getenv("VELOCITY_SIMD_TARGET"));
  return error;
}

// Before main (or when the Python module is loaded), so that kernels called without a
// Renderer (the unit tests' coverage and sampler checks) run the requested target too.
// The Renderer's constructor calls it again, which links this file and reports an error.
[[maybe_unused]] static const bool applied_at_start = (apply_target_request(), true);

}  // namespace velocity::simd
