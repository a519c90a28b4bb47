// The ASCII STL check (see stl_check.hpp for why it exists): a tokenizer that counts
// lines, and the grammar as a small state machine over keywords.
#include "io/stl_check.hpp"

#include <cstdint>

#include "io/text.hpp"
#include "velocity/error.hpp"

namespace velocity::detail {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

class Tokens {
 public:
  Tokens(std::string_view text, const std::string& path) : text_(text), path_(path) {}

  // The next whitespace-separated token; empty at the end of the text.
  std::string_view next() {
    skip_blanks();
    size_t start = pos_;
    while (pos_ < text_.size() && !is_blank(text_[pos_])) ++pos_;
    return text_.substr(start, pos_ - start);
  }
  // Skips the rest of the current line (a solid's name).
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
  }
  uint32_t line() const { return line_; }

  // A statement starts a line of its own and keeps to it ("facet normal X Y Z",
  // "vertex X Y Z"), as every writer puts it and as Assimp reads it: a normal broken
  // over two lines loads wrong there (and leaks memory).
  void expect_statement(std::string_view keyword) {
    uint32_t before = line_;
    std::string_view t = next();
    if (t != keyword) unexpected("'" + std::string(keyword) + "'", t);
    if (line_ == before) fail(path_, line_, "'" + std::string(keyword) + "' should start a line");
  }
  void expect_on_line(std::string_view keyword) {
    uint32_t before = line_;
    std::string_view t = next();
    if (t != keyword) unexpected("'" + std::string(keyword) + "'", t);
    if (line_ != before) fail(path_, line_, "'" + std::string(keyword) + "' should be on line " + std::to_string(before));
  }
  void expect_numbers(int n, std::string_view what) {
    uint32_t before = line_;
    for (int i = 0; i < n; ++i) {
      std::string_view t = next(), rest = t;
      float value;
      if (!parse_float(rest, value) || !rest.empty()) unexpected("a finite number (" + std::string(what) + ")", t);
      if (line_ != before) fail(path_, line_, std::string(what) + " should be on line " + std::to_string(before));
    }
  }
  [[noreturn]] void unexpected(const std::string& expected, std::string_view got) {
    if (got.empty()) fail(path_, line_, "the file ends where " + expected + " should be (file truncated?)");
    fail_expected(path_, line_, expected, got);
  }

 private:
  void skip_blanks() {
    while (pos_ < text_.size() && is_blank(text_[pos_])) {
      // A line ends at LF, CRLF or a lone CR.
      if (text_[pos_] == '\n' || (text_[pos_] == '\r' && (pos_ + 1 >= text_.size() || text_[pos_ + 1] != '\n'))) ++line_;
      ++pos_;
    }
  }

  std::string_view text_;
  const std::string& path_;
  size_t pos_ = 0;
  uint32_t line_ = 1;
};

}  // namespace

bool is_ascii_stl(std::string_view bytes) {
  if (bytes.size() >= 84) {
    const auto* b = reinterpret_cast<const uint8_t*>(bytes.data()) + 80;
    uint64_t count = uint64_t(b[0]) | uint64_t(b[1]) << 8 | uint64_t(b[2]) << 16 | uint64_t(b[3]) << 24;
    if (84 + 50 * count == bytes.size()) return false;
  }
  size_t i = 0;
  while (i < bytes.size() && is_blank(bytes[i])) ++i;
  return bytes.substr(i, 5) == "solid";
}

void check_ascii_stl(std::string_view bytes, const std::string& path) {
  Tokens tokens(bytes, path);
  std::string_view t = tokens.next();
  if (t.substr(0, 5) != "solid") tokens.unexpected("'solid'", t);
  while (!t.empty()) {
    // `t` is "solid" (perhaps with the name run on: "solidname"); the name is the rest
    // of the line.
    if (t.substr(0, 5) != "solid") tokens.unexpected("'solid' or the end of the file", t);
    tokens.skip_line();
    for (;;) {
      uint32_t before = tokens.line();
      t = tokens.next();
      if (t.substr(0, 8) == "endsolid") {
        tokens.skip_line();
        break;
      }
      if (t != "facet") tokens.unexpected("'facet' or 'endsolid'", t);
      if (tokens.line() == before) fail(path, tokens.line(), "'facet' should start a line");
      tokens.expect_on_line("normal");
      tokens.expect_numbers(3, "the facet normal");
      tokens.expect_statement("outer");
      tokens.expect_on_line("loop");
      for (int v = 0; v < 3; ++v) {
        tokens.expect_statement("vertex");
        tokens.expect_numbers(3, "the vertex");
      }
      tokens.expect_statement("endloop");
      tokens.expect_statement("endfacet");
    }
    t = tokens.next();
  }
}

}  // namespace velocity::detail
