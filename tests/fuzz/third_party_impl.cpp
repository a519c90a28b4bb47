// The libFuzzer build only: stb_image and tinyobjloader compiled into the fuzz targets
// from the same Debian headers the library uses, so that they are instrumented too
// (coverage feedback for the fuzzer, ASan for their reads and writes). The linker takes
// these definitions before the ones in libstb.so / libtinyobjloader.so.
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
