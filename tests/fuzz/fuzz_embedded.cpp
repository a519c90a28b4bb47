// Fuzz target: the images a glTF file carries inside it (io/gltf_appearance.hpp): the
// input as the text of a "data:" URI (base64 or percent-encoded), decoded, then as image
// bytes in memory (decode_image, as a buffer view's image is read), then a texture.
// Property: each decodes or throws velocity::Error; a decoded image is consistent.
#include "fuzz_util.hpp"
#include "io/gltf_appearance.hpp"
#include "velocity/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace velocity;
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  try {
    const std::string bytes = detail::decode_data_uri(input, "fuzz");
    fuzz_check(bytes.size() <= input.size());  // neither encoding grows
  } catch (const Error&) {
  }
  for (const std::string& uri : {"data:image/png;base64," + std::string(input), "data:," + std::string(input)}) {
    try {
      fuzz_check(detail::decode_data_uri(uri, "fuzz").size() <= input.size());
    } catch (const Error&) {
    }
  }
  Image image;
  try {
    image = decode_image(input, "fuzz");
  } catch (const Error&) {
    return 0;
  }
  fuzz::check_decoded_image(image);
  return 0;
}
