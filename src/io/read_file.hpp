// Internal: reading a whole file into memory for the loaders, with a size limit.
#pragma once

#include <cstddef>
#include <string>

namespace velocity::detail {

// Returns the bytes of the file at `path`. Throws velocity::Error naming the file when it
// does not exist, is a directory or another non-regular file, cannot be opened or read,
// or holds more than `max_bytes` (the caller passes LoadOptions::max_memory).
std::string read_file(const std::string& path, size_t max_bytes);

// The file name's extension after the last dot, lower-case, without the dot; empty when
// there is none ("models/CUBE.PLG" -> "plg").
std::string lower_extension(const std::string& path);

}  // namespace velocity::detail
