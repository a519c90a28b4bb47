// Replays a fuzz target (linked in: its LLVMFuzzerTestOneInput) over files and folders
// given on the command line, folders recursively, in sorted order: the corpus and the
// regressions, in the normal build, under ctest. No libFuzzer needed. A crash, a
// sanitizer report or an exception other than velocity::Error fails the run; the
// input's path is printed first, so the failing file is known.
//
//   velocity_fuzz_replay_asc tests/fuzz/corpus/asc tests/fuzz/regressions/asc
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  int missing = 0;
  for (int i = 1; i < argc; ++i) {
    fs::path p = argv[i];
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      for (const auto& e : fs::recursive_directory_iterator(p))
        if (e.is_regular_file() && e.path().filename().string()[0] != '.') files.push_back(e.path());
    } else if (fs::is_regular_file(p, ec)) {
      files.push_back(p);
    } else {
      std::fprintf(stderr, "replay: %s: not found (skipped)\n", p.c_str());
      ++missing;
    }
  }
  std::sort(files.begin(), files.end());
  size_t bytes = 0;
  for (const fs::path& f : files) {
    std::fprintf(stderr, "replay: %s\n", f.c_str());
    std::ifstream in(f, std::ios::binary);
    std::vector<uint8_t> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    bytes += data.size();
    // libFuzzer hands the target its own copy; do the same, so a read past the end of
    // the input is past the end of an allocation.
    std::vector<uint8_t> copy(data);
    LLVMFuzzerTestOneInput(copy.empty() ? nullptr : copy.data(), copy.size());
  }
  std::printf("replayed %zu inputs (%zu bytes)%s\n", files.size(), bytes,
              missing ? ", some paths were missing (see above)" : "");
  return files.empty() ? 1 : 0;
}
