// Reading whole files for the loaders: clear errors for the usual mistakes (a missing
// file, a directory, a file too big for the memory limit) instead of a failed parse.
#include "io/read_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "velocity/error.hpp"

namespace velocity::detail {

std::string read_file(const std::string& path, size_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw Error(path + ": no such file");
  if (fs::is_directory(status)) throw Error(path + ": is a directory, expected a file");
  if (!fs::is_regular_file(status)) throw Error(path + ": not a regular file");

  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw Error(path + ": cannot open (" + std::strerror(errno) + ")");

  // Check the size up front when the file system knows it, so a huge file fails before
  // any allocation; the read loop checks again in case the file grows meanwhile.
  uintmax_t size = fs::file_size(path, ec);
  auto too_big = [&](uintmax_t n) {
    return Error(path + ": file is " + std::to_string(n) + " bytes, more than the limit of " +
                 std::to_string(max_bytes) + " (LoadOptions::max_memory)");
  };
  if (!ec && size > max_bytes) throw too_big(size);

  std::string data;
  if (!ec) data.reserve(size_t(size));
  char buffer[1 << 16];
  for (;;) {
    size_t n = std::fread(buffer, 1, sizeof buffer, f.get());
    if (n > max_bytes - data.size()) throw too_big(data.size() + n);
    data.append(buffer, n);
    if (n < sizeof buffer) break;
  }
  if (std::ferror(f.get())) throw Error(path + ": read failed (" + std::strerror(errno) + ")");
  return data;
}

std::string lower_extension(const std::string& path) {
  size_t slash = path.find_last_of("/\\");
  size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
  return ext;
}

}  // namespace velocity::detail
