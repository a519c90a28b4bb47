// Fuzz target: the image reader (read_image: stb_image for PNG, JPEG, TGA, BMP, GIF,
// PPM, ...), then a texture made from the image. read_image takes a path, so the input
// goes through a file. In the libFuzzer build stb_image itself is compiled in with the
// sanitizers (stb_impl.cpp), so a bad read inside it is caught too.
// Property: it decodes or throws velocity::Error; a decoded image is consistent.
#include "fuzz_util.hpp"
#include "velocity/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace velocity;
  std::string path = fuzz::TempDir::get().write("fuzz.img", {reinterpret_cast<const char*>(data), size});
  Image image;
  try {
    image = read_image(path);
  } catch (const Error&) {
    return 0;
  }
  fuzz::check_decoded_image(image);
  return 0;
}
