// Internal helpers shared by the hand-written text readers (ASC, PLG): a line splitter
// that accepts LF, CRLF, lone CR and a missing final newline; number parsing with
// std::from_chars (no locale, no iostreams); and error messages that name the file,
// the line and what was expected.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "velocity/error.hpp"

namespace velocity::detail {

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline char to_lower(char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; }

inline std::string_view trim_left(std::string_view s) {
  size_t i = 0;
  while (i < s.size() && is_space(s[i])) ++i;
  return s.substr(i);
}
inline std::string_view trim_right(std::string_view s) {
  size_t n = s.size();
  while (n > 0 && is_space(s[n - 1])) --n;
  return s.substr(0, n);
}
inline std::string_view trim(std::string_view s) { return trim_right(trim_left(s)); }

// ASCII case-insensitive prefix test: writers differ in capitalisation, never in spelling.
inline bool starts_with_ci(std::string_view s, std::string_view prefix) {
  if (s.size() < prefix.size()) return false;
  for (size_t i = 0; i < prefix.size(); ++i)
    if (to_lower(s[i]) != to_lower(prefix[i])) return false;
  return true;
}

// Splits text into lines. A line ends at LF, CRLF or a lone CR (all three occur, even
// mixed in one file); the last line may have no terminator. Line numbers start at 1.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}

  // Sets `line` to the next line without its terminator; false at the end of the text.
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    size_t start = pos_, end = start;
    const char* p = text_.data();
    while (end < text_.size() && p[end] != '\n' && p[end] != '\r') ++end;
    line = text_.substr(start, end - start);
    pos_ = end;
    if (pos_ < text_.size()) {
      if (p[pos_] == '\r' && pos_ + 1 < text_.size() && p[pos_ + 1] == '\n') ++pos_;
      ++pos_;
    }
    ++number_;
    return true;
  }
  // Number of the line last returned by next().
  uint32_t number() const { return number_; }
  // Bytes not yet read: bounds how many more records the text can possibly hold.
  size_t bytes_left() const { return text_.size() - pos_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  uint32_t number_ = 0;
};

// A short, printable excerpt of `s` for an error message ("got '...'").
inline std::string excerpt(std::string_view s, size_t max_chars = 48) {
  s = trim(s);
  std::string out;
  for (size_t i = 0; i < s.size() && i < max_chars; ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += char(c);
    } else {
      static const char hex[] = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (s.size() > max_chars) out += "...";
  return out;
}

// "FILE:LINE: MESSAGE". Thrown for every malformed input.
[[noreturn]] inline void fail(const std::string& file, uint32_t line, const std::string& message) {
  throw Error(file + ":" + std::to_string(line) + ": " + message);
}
[[noreturn]] inline void fail_expected(const std::string& file, uint32_t line, std::string_view expected,
                                       std::string_view got) {
  std::string g = got.empty() ? std::string("the end of the line") : "'" + excerpt(got) + "'";
  fail(file, line, "expected " + std::string(expected) + ", got " + g);
}

// Parses a decimal float at the start of `s` ("-0", "2500", "0.5", "+1e3", "-0.000000")
// and advances `s` past it. Rejects inf, nan and values out of float range: a file
// that holds them is broken, and they would poison bounds and normals.
inline bool parse_float(std::string_view& s, float& out) {
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (first != last && *first == '+') ++first;  // from_chars rejects a leading '+'
  if (first == last || !(is_digit(*first) || *first == '-' || *first == '.')) return false;
  auto [ptr, ec] = std::from_chars(first, last, out, std::chars_format::general);
  if (ec != std::errc() || !std::isfinite(out)) return false;
  s.remove_prefix(size_t(ptr - s.data()));
  return true;
}

// Parses an unsigned decimal integer that fits in uint32_t and advances `s` past it.
inline bool parse_uint(std::string_view& s, uint32_t& out) {
  const char* first = s.data();
  const char* last = s.data() + s.size();
  if (first != last && *first == '+') ++first;
  if (first == last || !is_digit(*first)) return false;
  auto [ptr, ec] = std::from_chars(first, last, out, 10);
  if (ec != std::errc()) return false;
  s.remove_prefix(size_t(ptr - s.data()));
  return true;
}

// Skips spaces and tabs, then consumes `key` (case-insensitive) if it is next.
inline bool consume_key(std::string_view& s, std::string_view key) {
  std::string_view t = trim_left(s);
  if (!starts_with_ci(t, key)) return false;
  s = t.substr(key.size());
  return true;
}

}  // namespace velocity::detail
