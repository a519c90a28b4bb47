// Helpers for the reader tests (ASC, PLG, PCX, corpus): where the data is, reading it,
// and the "loads or throws velocity::Error, never anything else" check.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "velocity/error.hpp"

namespace velocity::test {

// The real third-party files, read in place (see ../shared/data/SOURCES.md).
inline std::string shared_data(const std::string& relative) { return std::string(VELOCITY_SHARED_DATA) + "/" + relative; }
// The project's own test files (tests/data).
inline std::string test_data(const std::string& relative) { return std::string(VELOCITY_TEST_DATA) + "/" + relative; }

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Skips the current test, saying why, when a shared file is missing.
#define VELOCITY_REQUIRE_SHARED(path)                                                                  \
  do {                                                                                                 \
    if (!std::filesystem::exists(path))                                                                \
      GTEST_SKIP() << "skipped: " << (path) << " is missing (the shared test data lives beside the "   \
                   << "repository in ../shared/data; see SOURCES.md)";                                 \
  } while (0)

// Runs `load`; passes when it returns or throws velocity::Error. Returns true if it loaded.
template <class F>
bool loads_or_throws_error(F&& load, const std::string& what) {
  try {
    load();
    return true;
  } catch (const velocity::Error&) {
    return false;
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": threw a " << typeid(e).name() << " instead of velocity::Error: " << e.what();
  } catch (...) {
    ADD_FAILURE() << what << ": threw something that is not a std::exception";
  }
  return false;
}

// Deterministic pseudo-random numbers for the mutation tests (xorshift32).
struct Rng {
  uint32_t state = 2463534242u;
  uint32_t next() {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return state;
  }
};

}  // namespace velocity::test
