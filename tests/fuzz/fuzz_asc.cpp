// Fuzz target: the 3D Studio ASCII reader (parse_asc). The input is the file's text.
// Property: it loads or throws velocity::Error; what loads is a consistent model.
#include "fuzz_util.hpp"
#include "velocity/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace velocity;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  Model model;
  try {
    model = parse_asc(text, "fuzz.asc", fuzz::fuzz_load_options());
  } catch (const Error&) {
    return 0;
  }
  fuzz::check_model(model);  // a velocity::Error here is a bug: it escapes
  return 0;
}
