// Which instruction set the kernels run with. Highway picks the best one the processor
// has; VELOCITY_SIMD_TARGET names another of those compiled in (AVX3, AVX2, SSE4,
// SCALAR: Highway's names), so that every compiled kernel can be tested on one machine
// (scripts/simd_targets.sh runs the whole suite once per target).
#pragma once

#include <string>

namespace velocity::simd {

// Applies VELOCITY_SIMD_TARGET once per process (later calls return the first result).
// Returns an empty string when the variable is unset or was applied; otherwise what was
// wrong (an unknown name, or a target this build or this processor lacks), for the
// caller to throw as velocity::Error.
const std::string& apply_target_request();

// The targets this build compiled and this processor runs, best first, space-separated
// ("AVX3 AVX2 SSE4 SCALAR"): what VELOCITY_SIMD_TARGET may name.
std::string available_targets();

}  // namespace velocity::simd
