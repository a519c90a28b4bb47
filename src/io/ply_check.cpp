// The PLY structural check (see ply_check.hpp for why it exists). It reads the format as
// Paul Bourke's description and the common writers have it: a text header of
// `format`, `element NAME COUNT` and `property [list CT] T NAME` lines up to
// `end_header` (other lines, `comment` and `obj_info` among them, are skipped as Assimp
// skips them); then the elements in header order, each instance on its own line
// (ASCII) or packed with no padding (binary, little or big endian).
#include "io/ply_check.hpp"

#include <charconv>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "io/text.hpp"
#include "velocity/error.hpp"

namespace velocity::detail {

namespace {

enum class Type : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

size_t size_of(Type t) {
  switch (t) {
    case Type::Int8: case Type::UInt8: return 1;
    case Type::Int16: case Type::UInt16: return 2;
    case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 0;
}

bool is_integer(Type t) { return t != Type::Float32 && t != Type::Float64; }

// Both spellings of the specification ("uchar") and of later writers ("uint8").
std::optional<Type> parse_type(std::string_view s) {
  struct Name { const char* name; Type type; };
  static const Name names[] = {
      {"char", Type::Int8},     {"int8", Type::Int8},      {"uchar", Type::UInt8},   {"uint8", Type::UInt8},
      {"short", Type::Int16},   {"int16", Type::Int16},    {"ushort", Type::UInt16}, {"uint16", Type::UInt16},
      {"int", Type::Int32},     {"int32", Type::Int32},    {"uint", Type::UInt32},   {"uint32", Type::UInt32},
      {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64}, {"float64", Type::Float64}};
  for (const Name& n : names)
    if (s == n.name) return n.type;
  return std::nullopt;
}

struct Property {
  std::string name;
  bool list = false;
  Type count_type = Type::UInt8;
  Type type = Type::Float32;
  bool vertex_indices = false;  // a face's corner list: each value must name a vertex
};

struct Element {
  std::string name;
  uint32_t count = 0;
  uint32_t line = 0;
  std::vector<Property> properties;
};

enum class Format { Ascii, BinaryLittle, BinaryBig };

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  size_t body = 0;        // offset of the first byte after the header
  uint32_t body_line = 0;  // number of the header's last line
  uint32_t vertex_count = 0;
};

Header parse_header(std::string_view bytes, const std::string& path) {
  LineReader lines(bytes);
  std::string_view line;
  if (!lines.next(line) || trim(line) != "ply") fail(path, 1, "not a PLY file: expected 'ply' on the first line");
  Header h;
  bool have_format = false;
  // Assimp reads an element's properties up to the first line that is not a property
  // or a comment, and skips any 'property' line after that one until the next element:
  // a file whose property list is broken by another line means to Assimp what it does
  // not mean here, and binary data would be read in another layout. The line that broke
  // the list, or 0.
  uint32_t list_broken_at = 0;
  std::string_view list_broken_by;
  while (true) {
    if (!lines.next(line)) throw Error(path + ": PLY header has no 'end_header' line (file truncated?)");
    const uint32_t n = lines.number();
    std::vector<std::string_view> t = split(line);
    if (t.empty()) fail_expected(path, n, "a PLY header line", line);
    const bool comment = t[0] == "comment" && !(t.size() > 1 && t[1] == "TextureFile");  // Assimp: an element
    const bool known = comment || t[0] == "element" || t[0] == "property" || t[0] == "end_header";
    if (!known && !h.elements.empty() && !list_broken_at) list_broken_at = n, list_broken_by = line;
    if (t[0] == "element") list_broken_at = 0;
    if (t[0] == "property" && list_broken_at)
      fail(path, n, "'property' after line " + std::to_string(list_broken_at) + " ('" + std::string(trim(list_broken_by)) +
                        "'), which ends the element's property list for Assimp (make that line a comment)");
    if (t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") {
      if (t.size() != 1) fail_expected(path, n, "nothing after 'end_header'", line);
      break;
    }
    if (t[0] == "format") {
      if (have_format) fail(path, n, "second 'format' line");
      if (t.size() != 3 || t[2] != "1.0")
        fail_expected(path, n, "'format ascii|binary_little_endian|binary_big_endian 1.0'", line);
      if (t[1] == "ascii") h.format = Format::Ascii;
      else if (t[1] == "binary_little_endian") h.format = Format::BinaryLittle;
      else if (t[1] == "binary_big_endian") h.format = Format::BinaryBig;
      else fail_expected(path, n, "ascii, binary_little_endian or binary_big_endian", t[1]);
      have_format = true;
      continue;
    }
    if (!have_format) fail_expected(path, n, "the 'format' line", line);
    if (t[0] == "element") {
      std::string_view count = t.size() == 3 ? t[2] : std::string_view();
      Element e;
      if (t.size() != 3 || !parse_uint(count, e.count) || !count.empty())
        fail_expected(path, n, "'element NAME COUNT'", line);
      e.name = std::string(t[1]);
      e.line = n;
      for (const Element& other : h.elements)
        if (other.name == e.name) fail(path, n, "element '" + e.name + "' declared twice");
      h.elements.push_back(std::move(e));
      continue;
    }
    if (t[0] == "property") {
      if (h.elements.empty()) fail(path, n, "'property' before any 'element'");
      Property p;
      if (t.size() == 5 && t[1] == "list") {
        auto ct = parse_type(t[2]);
        auto vt = parse_type(t[3]);
        if (!ct || !is_integer(*ct)) fail_expected(path, n, "an integer type for the list length", t[2]);
        if (!vt) fail_expected(path, n, "a PLY type (char, uchar, short, ushort, int, uint, float, double)", t[3]);
        p.list = true;
        p.count_type = *ct;
        p.type = *vt;
        p.name = std::string(t[4]);
      } else if (t.size() == 3) {
        auto vt = parse_type(t[1]);
        if (!vt) fail_expected(path, n, "a PLY type (char, uchar, short, ushort, int, uint, float, double)", t[1]);
        p.type = *vt;
        p.name = std::string(t[2]);
      } else {
        fail_expected(path, n, "'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'", line);
      }
      Element& e = h.elements.back();
      p.vertex_indices = e.name == "face" && p.list && (p.name == "vertex_indices" || p.name == "vertex_index");
      if (p.vertex_indices && !is_integer(p.type)) fail(path, n, "face vertex indices must have an integer type");
      for (const Property& other : e.properties)
        if (other.name == p.name) fail(path, n, "property '" + p.name + "' declared twice");
      e.properties.push_back(std::move(p));
      continue;
    }
    // Any other line is skipped, as Assimp does: Blender 2.47 wrote its "Created by"
    // line without the 'comment' keyword (Wuson.ply).
  }
  if (!have_format) throw Error(path + ": PLY header has no 'format' line");
  for (const Element& e : h.elements) {
    if (e.count > 0 && e.properties.empty())
      fail(path, e.line, "element '" + e.name + "' has " + std::to_string(e.count) + " instances but no properties");
    if (e.name == "vertex") h.vertex_count = e.count;
  }
  h.body = bytes.size() - lines.bytes_left();
  h.body_line = lines.number();
  return h;
}

std::string instance_name(const Element& e, uint64_t i) {
  return "element '" + e.name + "' #" + std::to_string(i);
}

// --- ASCII: one instance per line, at least as many numbers as it needs.

bool parse_integer(std::string_view s, int64_t& out) {
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (first != last && *first == '+') ++first;
  auto [ptr, ec] = std::from_chars(first, last, out);
  return ec == std::errc() && ptr == last;
}

bool parse_number(std::string_view s) {
  float f;
  return parse_float(s, f) && s.empty();
}

void check_ascii(std::string_view bytes, const Header& h, const std::string& path) {
  LineReader lines(bytes.substr(h.body));
  std::string_view line;
  for (const Element& e : h.elements) {
    for (uint32_t i = 0; i < e.count; ++i) {
      if (!lines.next(line))
        throw Error(path + ": PLY file ends before " + instance_name(e, i) + " of " + std::to_string(e.count) +
                    " (file truncated?)");
      const uint32_t n = h.body_line + lines.number();
      std::vector<std::string_view> t = split(line);
      size_t at = 0;
      for (const Property& p : e.properties) {
        if (!p.list) {
          if (at >= t.size()) fail_expected(path, n, "a value for '" + p.name + "' of " + instance_name(e, i), "");
          if (!parse_number(t[at])) fail_expected(path, n, "a number for '" + p.name + "'", t[at]);
          ++at;
          continue;
        }
        int64_t count = -1;
        if (at >= t.size() || !parse_integer(t[at], count) || count < 0)
          fail_expected(path, n, "the length of list '" + p.name + "' of " + instance_name(e, i),
                        at < t.size() ? t[at] : std::string_view());
        ++at;
        if (uint64_t(count) > t.size() - at)
          fail(path, n, "list '" + p.name + "' of " + instance_name(e, i) + " has length " + std::to_string(count) +
                            " but only " + std::to_string(t.size() - at) + " values follow on the line");
        for (int64_t k = 0; k < count; ++k, ++at) {
          if (p.vertex_indices) {
            int64_t v = -1;
            if (!parse_integer(t[at], v)) fail_expected(path, n, "a vertex index", t[at]);
            if (v < 0 || v >= int64_t(h.vertex_count))
              fail(path, n, instance_name(e, i) + " uses vertex " + std::to_string(v) + ", but there are only " +
                                std::to_string(h.vertex_count));
          } else if (!parse_number(t[at])) {
            fail_expected(path, n, "a number in list '" + p.name + "'", t[at]);
          }
        }
      }
    }
  }
}

// --- binary: packed values, the list lengths and face indices read in the file's byte order.

int64_t read_integer(const char* p, Type t, bool big_endian) {
  uint8_t b[4] = {0, 0, 0, 0};
  size_t n = size_of(t);
  for (size_t k = 0; k < n; ++k) b[k] = uint8_t(p[big_endian ? n - 1 - k : k]);
  uint32_t u = uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
  switch (t) {
    case Type::Int8: return int8_t(u);
    case Type::UInt8: return uint8_t(u);
    case Type::Int16: return int16_t(u);
    case Type::UInt16: return uint16_t(u);
    case Type::Int32: return int32_t(u);
    default: return u;
  }
}

void check_binary(std::string_view bytes, const Header& h, const std::string& path) {
  const bool big = h.format == Format::BinaryBig;
  const char* data = bytes.data();
  size_t at = h.body;
  auto need = [&](size_t n, const Element& e, uint64_t i) {
    if (n > bytes.size() - at)
      throw Error(path + ": PLY file ends inside " + instance_name(e, i) + " of " + std::to_string(e.count) +
                  " (file truncated?)");
  };
  for (const Element& e : h.elements) {
    for (uint32_t i = 0; i < e.count; ++i) {
      for (const Property& p : e.properties) {
        if (!p.list) {
          need(size_of(p.type), e, i);
          at += size_of(p.type);
          continue;
        }
        need(size_of(p.count_type), e, i);
        int64_t count = read_integer(data + at, p.count_type, big);
        at += size_of(p.count_type);
        if (count < 0)
          throw Error(path + ": list '" + p.name + "' of " + instance_name(e, i) + " has negative length " +
                      std::to_string(count));
        const size_t size = size_of(p.type);
        need(size_t(count) * size, e, i);  // count < 2^32 and size <= 8: no overflow
        if (p.vertex_indices) {
          for (int64_t k = 0; k < count; ++k) {
            int64_t v = read_integer(data + at + size_t(k) * size, p.type, big);
            if (v < 0 || v >= int64_t(h.vertex_count))
              throw Error(path + ": " + instance_name(e, i) + " uses vertex " + std::to_string(v) +
                          ", but there are only " + std::to_string(h.vertex_count));
          }
        }
        at += size_t(count) * size;
      }
    }
  }
}

}  // namespace

bool looks_like_ply(std::string_view bytes) {
  return bytes.size() >= 3 && to_lower(bytes[0]) == 'p' && to_lower(bytes[1]) == 'l' && to_lower(bytes[2]) == 'y';
}

void check_ply(std::string_view bytes, const std::string& path) {
  Header h = parse_header(bytes, path);
  // Assimp reads the text parts as C strings and also ends a line at NUL and form feed,
  // where LineReader does not: such a byte would make the two disagree on the lines.
  std::string_view text = h.format == Format::Ascii ? bytes : bytes.substr(0, h.body);
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\0' || text[i] == '\f' || text[i] == '\v')
      throw Error(path + ": byte " + std::to_string(i) + " of the PLY " +
                  (i < h.body ? "header" : "text") + " is a control character (" + std::to_string(int(text[i])) +
                  "); the file is damaged");
  if (h.format == Format::Ascii)
    check_ascii(bytes, h, path);
  else
    check_binary(bytes, h, path);
}

}  // namespace velocity::detail
