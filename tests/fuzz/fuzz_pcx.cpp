// Fuzz target: the PCX decoder (decode_pcx). The input is the file's bytes.
// Property: it decodes or throws velocity::Error; a decoded image is consistent and
// makes a texture (its whole mip chain).
#include <span>

#include "fuzz_util.hpp"
#include "velocity/error.hpp"
#include "velocity/pcx.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace velocity;
  Image image;
  try {
    image = decode_pcx(std::span<const uint8_t>(data, size), "fuzz.pcx");
  } catch (const Error&) {
    return 0;
  }
  fuzz::check_decoded_image(image);
  return 0;
}
