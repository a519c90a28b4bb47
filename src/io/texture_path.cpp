// Finding the image a model file names as its texture. Files written on one machine
// and read on another rarely name their textures exactly: 3D Studio writes 8.3 names in
// upper case ("IMAGE1.JPG" for image1.jpg), Windows tools write backslashes and
// absolute paths ("C:\models\tex\wood.jpg"), glTF writes percent-encoded URIs. The
// lookup tries, in order, what the file wrote and then more forgiving spellings, always
// inside the model's own folder for relative names.
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "velocity/load.hpp"

namespace velocity {

namespace {

namespace fs = std::filesystem;

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'A' && x <= 'Z') x = char(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = char(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

// `dir` / `relative`, each component matched exactly when it exists, else by an ASCII
// case-insensitive scan of its folder (the first match in name order, so the result
// does not depend on the file system's listing order). Empty when nothing matches.
fs::path find_ignoring_case(const fs::path& dir, const fs::path& relative) {
  fs::path at = dir;
  for (const fs::path& part : relative) {
    const std::string name = part.string();
    if (name.empty() || name == ".") continue;
    if (name == "..") {
      at /= part;
      continue;
    }
    std::error_code ec;
    if (fs::exists(at / part, ec)) {
      at /= part;
      continue;
    }
    std::string best;
    for (fs::directory_iterator it(at.empty() ? fs::path(".") : at, ec), end; !ec && it != end; it.increment(ec)) {
      std::string candidate = it->path().filename().string();
      if (equal_ignoring_case(candidate, name) && (best.empty() || candidate < best)) best = candidate;
    }
    if (best.empty()) return {};
    at /= best;
  }
  return is_file(at) ? at : fs::path();
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// glTF image URIs are percent-encoded ("my%20texture.png").
std::string percent_decoded(std::string_view s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    int hi = 0, lo = 0;
    if (s[i] == '%' && i + 2 < s.size() && (hi = hex_value(s[i + 1])) >= 0 && (lo = hex_value(s[i + 2])) >= 0) {
      out += char(hi * 16 + lo);
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

}  // namespace

std::string resolve_texture_path(const std::string& model_path, const std::string& name) {
  if (name.empty() || name[0] == '*') return {};  // "*N": embedded in the model file itself
  if (name.rfind("data:", 0) == 0) return {};     // a glTF data URI: embedded too

  const fs::path dir = fs::path(model_path).parent_path();

  // The spellings to try, most literal first: as written, with Windows separators
  // turned round, percent-decoded. Each is tried exactly, then ignoring case.
  std::vector<std::string> spellings{name};
  std::string slashed = name;
  for (char& c : slashed) c = c == '\\' ? '/' : c;
  if (slashed != name) spellings.push_back(slashed);
  std::string decoded = percent_decoded(slashed);
  if (decoded != slashed) spellings.push_back(decoded);

  for (const std::string& s : spellings) {
    fs::path p(s);
    // A drive-letter path ("C:/x/y.jpg") is absolute on the machine that wrote it only.
    bool foreign_absolute = s.size() > 2 && s[1] == ':' && (s[2] == '/' || s[2] == '\\');
    if (foreign_absolute) continue;
    fs::path full = p.is_absolute() ? p : dir / p;
    if (is_file(full)) return full.string();
    fs::path found = p.is_absolute() ? find_ignoring_case(p.root_path(), p.relative_path())
                                     : find_ignoring_case(dir, p);
    if (!found.empty()) return found.string();
  }
  // Last resort: the bare file name beside the model (the folder it was written in is
  // usually not the folder it was copied to).
  fs::path base = fs::path(spellings.back()).filename();
  if (!base.empty() && base != fs::path(spellings.back())) {
    if (is_file(dir / base)) return (dir / base).string();
    fs::path found = find_ignoring_case(dir, base);
    if (!found.empty()) return found.string();
  }
  return {};
}

}  // namespace velocity
