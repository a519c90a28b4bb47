// PLG object files: REND386's format as used by LaMothe's "Black Art of 3D Game
// Programming" (1995), and the "PLX" variant of his "Tricks of the 3D Game Programming
// Gurus" (2003), which keeps the layout and redefines the polygon descriptor.
//
//   ; comment            (';' in Black Art, '#' in Tricks; full-line or trailing)
//   name 8 6             object name, vertex count, polygon count
//   -20 20 20            one vertex per line: x y z (integers or decimals)
//   0x109f 4 0 3 2 1     descriptor (decimal or 0x hex, 16 bits), n, then n vertex numbers
//
// Three steps, as for every reader: parse (records and numbers, indices against the
// header's vertex count), validate (header counts against the records), build (axes,
// winding, triangles, materials, normals).
//
// Coordinates and winding. Both books use a left-handed world: x right, y up, z into
// the screen. Velocity is right-handed with the camera looking down -Z, so z is negated:
// a mirror, which turns the world into Velocity's and leaves what a viewer sees as it
// was (an object in front of the books' camera is in front of Velocity's, x still to
// the right). Each book's own back-face test then says which vertex order is the front:
//   * Black Art (BLACK11.C/BLACK17.C, Remove_Backfaces_And_Shade): a polygon faces the
//     viewer when (v2 - v0) x (v1 - v0) points at the eye, i.e. its vertices run
//     counter-clockwise on screen. Velocity's front is counter-clockwise too: the order
//     is kept.
//   * Tricks (T3DLIB5, Remove_Backfaces_OBJECT4DV1): the front normal is
//     (v1 - v0) x (v2 - v0), clockwise on screen ("vertices are in cw order"): the order
//     is reversed.
// Both are checked on the books' cubes (CUBE.PLG, cube1.plg): every face points out.
//
// Which dialect a file is: PLX when its name ends in .plx, when it has '#' comments
// (every Tricks file does, none of Black Art's) or when a descriptor sets bit 15 (the
// RGB flag; Black Art's shading values stop at 3). Otherwise Black Art.
#include "io/plg.hpp"

#include <array>
#include <cstdio>
#include <memory>
#include <unordered_map>

#include "io/read_file.hpp"
#include "io/text.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"

namespace velocity {

namespace detail {

namespace {

// The IBM VGA's power-on 256-colour palette, the one mode 13h starts with (IBM VGA
// Technical Reference; the same table is in every VGA BIOS and emulator), in 6-bit DAC
// units (0-63). Rather than 768 literals it is built from its structure:
//   0-15     the 16 EGA colours;
//   16-31    a grey ramp;
//   32-247   nine blocks of 24 hues (blue -> magenta -> red -> yellow -> green -> cyan ->
//            back to blue, four steps between each), one block per combination of
//            intensity (high, medium, low) and saturation (high, moderate, low);
//   248-255  black.
struct Rgb6 {
  uint8_t r, g, b;
};

constexpr std::array<Rgb6, 256> make_vga_palette() {
  std::array<Rgb6, 256> p{};
  constexpr Rgb6 ega[16] = {{0, 0, 0},    {0, 0, 42},   {0, 42, 0},   {0, 42, 42},  {42, 0, 0},   {42, 0, 42},
                            {42, 21, 0},  {42, 42, 42}, {21, 21, 21}, {21, 21, 63}, {21, 63, 21}, {21, 63, 63},
                            {63, 21, 21}, {63, 21, 63}, {63, 63, 21}, {63, 63, 63}};
  constexpr uint8_t grey[16] = {0, 5, 8, 11, 14, 17, 20, 24, 28, 32, 36, 40, 45, 50, 56, 63};
  // The five levels each channel steps through within a block, darkest first.
  constexpr uint8_t levels[9][5] = {
      {0, 16, 31, 47, 63},  {31, 39, 47, 55, 63}, {45, 49, 54, 58, 63},  // high intensity
      {0, 7, 14, 21, 28},   {14, 17, 21, 24, 28}, {20, 22, 24, 26, 28},  // medium intensity
      {0, 4, 8, 12, 16},    {8, 10, 12, 14, 16},  {11, 12, 13, 15, 16},  // low intensity
  };
  // Level of (r, g, b) for each of the 24 hues, starting at blue.
  constexpr uint8_t hue[24][3] = {{0, 0, 4}, {1, 0, 4}, {2, 0, 4}, {3, 0, 4}, {4, 0, 4}, {4, 0, 3},
                                  {4, 0, 2}, {4, 0, 1}, {4, 0, 0}, {4, 1, 0}, {4, 2, 0}, {4, 3, 0},
                                  {4, 4, 0}, {3, 4, 0}, {2, 4, 0}, {1, 4, 0}, {0, 4, 0}, {0, 4, 1},
                                  {0, 4, 2}, {0, 4, 3}, {0, 4, 4}, {0, 3, 4}, {0, 2, 4}, {0, 1, 4}};
  for (int i = 0; i < 16; ++i) p[i] = ega[i];
  for (int i = 0; i < 16; ++i) p[16 + i] = {grey[i], grey[i], grey[i]};
  for (int block = 0; block < 9; ++block)
    for (int h = 0; h < 24; ++h) {
      const uint8_t* l = levels[block];
      p[32 + block * 24 + h] = {l[hue[h][0]], l[hue[h][1]], l[hue[h][2]]};
    }
  return p;  // 248-255 stay black
}

constexpr std::array<Rgb6, 256> kVgaPalette = make_vga_palette();

}  // namespace

Vec3 vga_palette(uint8_t index) {
  Rgb6 c = kVgaPalette[index];
  return Vec3{float(c.r), float(c.g), float(c.b)} / 63.0f;
}

Material plg_material(uint16_t d, PlgDialect dialect) {
  Material m;
  char name[8];
  std::snprintf(name, sizeof name, "0x%04x", unsigned(d));
  m.name = name;
  if (dialect == PlgDialect::BlackArt) {
    m.color = vga_palette(uint8_t(d & 0xff));
    // 1 flat (lit); constant, metallic and glass are one unlit colour a face.
    m.shading = ((d >> 12) & 0xf) == 1 ? Shading::Flat : Shading::Unlit;
    m.two_sided = ((d >> 8) & 0xf) != 0;
    return m;
  }
  if (d & 0x8000) {
    // RGB 4.4.4: 0xf is full intensity, so each nibble is n / 15 (Tricks scaled by 16,
    // which tops out at 240/255; the nibble's own range is the intent).
    m.color = Vec3{float((d >> 8) & 0xf), float((d >> 4) & 0xf), float(d & 0xf)} / 15.0f;
  } else {
    m.color = vga_palette(uint8_t(d & 0xff));
  }
  switch ((d >> 13) & 3) {
    case 0: m.shading = Shading::Unlit; break;  // pure / constant
    case 1: m.shading = Shading::Flat; break;
    case 2: m.shading = Shading::Gouraud; break;
    case 3: m.shading = Shading::Phong; break;
  }
  m.two_sided = (d & 0x1000) != 0;
  return m;
}

}  // namespace detail

namespace {

using namespace detail;

// Shortest possible records, to bound reservations by what the text can still hold:
// "0 0 0\n" and "0 3 0 0 0\n".
constexpr size_t kMinVertexLineBytes = 6;
constexpr size_t kMinPolygonLineBytes = 10;
// Bytes the finished mesh needs per vertex and per polygon (a quad's two triangles,
// their materials), to hold a file to LoadOptions::max_memory.
constexpr size_t kBytesPerVertex = 48;
constexpr size_t kBytesPerPolygon = 48;

struct PlgPolygon {
  uint16_t descriptor = 0;
  uint32_t first = 0, count = 0;  // range in PlgFile::indices
};

struct PlgFile {
  std::string name;
  uint32_t header_line = 0, last_line = 0;
  uint32_t declared_vertices = 0, declared_polygons = 0;
  std::vector<Vec3> vertices;
  std::vector<PlgPolygon> polygons;
  std::vector<uint32_t> indices;
  bool hash_comments = false;
};

// The next whitespace-separated token of `s`, removed from it; empty at the end.
std::string_view next_token(std::string_view& s) {
  s = trim_left(s);
  size_t n = 0;
  while (n < s.size() && !is_space(s[n])) ++n;
  std::string_view t = s.substr(0, n);
  s.remove_prefix(n);
  return t;
}

// A whole token as a float / unsigned integer (nothing may follow the number).
bool token_float(std::string_view t, float& out) { return parse_float(t, out) && t.empty(); }
bool token_uint(std::string_view t, uint32_t& out) { return parse_uint(t, out) && t.empty(); }

// "0x109f", "0X109F" or "4255", at most 16 bits.
bool token_descriptor(std::string_view t, uint16_t& out) {
  uint32_t v = 0;
  if (t.size() > 2 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) {
    auto [ptr, ec] = std::from_chars(t.data() + 2, t.data() + t.size(), v, 16);
    if (ec != std::errc() || ptr != t.data() + t.size()) return false;
  } else if (!token_uint(t, v)) {
    return false;
  }
  if (v > 0xffff) return false;
  out = uint16_t(v);
  return true;
}

class PlgParser {
 public:
  PlgParser(std::string_view text, const std::string& file, const LoadOptions& options)
      : lines_(text), file_(file), options_(options) {}

  PlgFile parse() {
    std::string_view raw;
    while (lines_.next(raw)) {
      std::string_view s = trim(strip_comment(raw));
      if (s.empty()) continue;
      if (!have_header_)
        parse_header(s);
      else if (out_.vertices.size() < out_.declared_vertices)
        parse_vertex(s);
      else if (out_.polygons.size() < out_.declared_polygons)
        parse_polygon(s);
      else
        fail_expected(file_, lines_.number(),
                      "the end of the file after " + std::to_string(out_.declared_polygons) +
                          " polygons (header, line " + std::to_string(out_.header_line) + ")",
                      s);
    }
    out_.last_line = lines_.number();
    return std::move(out_);
  }

 private:
  std::string_view strip_comment(std::string_view s) {
    size_t c = s.find_first_of(";#");
    if (c == std::string_view::npos) return s;
    if (s[c] == '#') out_.hash_comments = true;
    return s.substr(0, c);
  }

  void parse_header(std::string_view s) {
    std::string_view rest = s;
    std::string_view name = next_token(rest);
    if (!token_uint(next_token(rest), out_.declared_vertices) ||
        !token_uint(next_token(rest), out_.declared_polygons) || !trim(rest).empty())
      fail_expected(file_, lines_.number(), "a PLG header 'name vertex_count polygon_count' (is this a PLG file?)", s);
    out_.name = std::string(name);
    out_.header_line = lines_.number();
    have_header_ = true;

    // The counts are untrusted: refuse what max_memory cannot hold, and reserve no more
    // than the rest of the text could describe.
    size_t need = size_t(out_.declared_vertices) * kBytesPerVertex + size_t(out_.declared_polygons) * kBytesPerPolygon;
    if (need > options_.max_memory)
      fail(file_, lines_.number(),
           "the header declares " + std::to_string(out_.declared_vertices) + " vertices and " +
               std::to_string(out_.declared_polygons) + " polygons, more than LoadOptions::max_memory allows");
    size_t left = lines_.bytes_left();
    out_.vertices.reserve(std::min<size_t>(out_.declared_vertices, left / kMinVertexLineBytes));
    out_.polygons.reserve(std::min<size_t>(out_.declared_polygons, left / kMinPolygonLineBytes));
  }

  void parse_vertex(std::string_view s) {
    std::string_view rest = s;
    Vec3 p;
    if (!token_float(next_token(rest), p.x) || !token_float(next_token(rest), p.y) ||
        !token_float(next_token(rest), p.z) || !trim(rest).empty())
      fail_expected(file_, lines_.number(),
                    "vertex " + std::to_string(out_.vertices.size()) + " of " +
                        std::to_string(out_.declared_vertices) + " as 'x y z' (finite numbers)",
                    s);
    out_.vertices.push_back(p);
  }

  void parse_polygon(std::string_view s) {
    std::string_view rest = s;
    PlgPolygon poly;
    std::string_view t = next_token(rest);
    if (!token_descriptor(t, poly.descriptor))
      fail_expected(file_, lines_.number(), "a 16-bit polygon descriptor (decimal or 0x hex)", t.empty() ? s : t);
    t = next_token(rest);
    if (!token_uint(t, poly.count) || poly.count == 0)
      fail_expected(file_, lines_.number(), "the polygon's vertex count (1 or more)", t);
    poly.first = uint32_t(out_.indices.size());
    for (uint32_t i = 0; i < poly.count; ++i) {
      uint32_t v = 0;
      t = next_token(rest);
      if (!token_uint(t, v) || v >= out_.declared_vertices)
        fail_expected(file_, lines_.number(),
                      "vertex number " + std::to_string(i + 1) + " of " + std::to_string(poly.count) + ", below " +
                          std::to_string(out_.declared_vertices),
                      t);
      out_.indices.push_back(v);
    }
    if (!trim(rest).empty())
      fail_expected(file_, lines_.number(),
                    "the end of the line after " + std::to_string(poly.count) + " vertex numbers", rest);
    out_.polygons.push_back(poly);
  }

  LineReader lines_;
  const std::string& file_;
  const LoadOptions& options_;
  PlgFile out_;
  bool have_header_ = false;
};

void validate(const PlgFile& f, const std::string& file) {
  if (f.header_line == 0)
    fail(file, std::max<uint32_t>(f.last_line, 1), "expected a PLG header 'name vertex_count polygon_count', got none");
  if (f.vertices.size() != f.declared_vertices)
    fail(file, f.header_line,
         "expected " + std::to_string(f.declared_vertices) + " vertices (header), got " +
             std::to_string(f.vertices.size()));
  if (f.polygons.size() != f.declared_polygons)
    fail(file, f.header_line,
         "expected " + std::to_string(f.declared_polygons) + " polygons (header), got " +
             std::to_string(f.polygons.size()));
}

PlgDialect dialect_of(const PlgFile& f, const std::string& name) {
  if (f.hash_comments || lower_extension(name) == "plx") return PlgDialect::Plx;
  for (const PlgPolygon& p : f.polygons)
    if (p.descriptor & 0x8000) return PlgDialect::Plx;
  return PlgDialect::BlackArt;
}

Model build(PlgFile& f, const std::string& name) {
  PlgDialect dialect = dialect_of(f, name);
  Mesh m;
  m.name = f.name;
  m.positions = std::move(f.vertices);
  for (Vec3& p : m.positions) p.z = -p.z;  // left-handed -> right-handed (see the top)

  std::unordered_map<uint16_t, uint32_t> material_of;
  bool reverse = dialect == PlgDialect::Plx;  // Tricks lists fronts clockwise
  for (const PlgPolygon& poly : f.polygons) {
    // REND386 allows 1- and 2-vertex "polygons" (points, lines): no triangles to draw.
    if (poly.count < 3) continue;
    auto [it, added] = material_of.try_emplace(poly.descriptor, uint32_t(m.materials.size()));
    if (added) m.materials.push_back(plg_material(poly.descriptor, dialect));
    const uint32_t* v = &f.indices[poly.first];
    auto at = [&](uint32_t i) { return v[reverse ? poly.count - 1 - i : i]; };
    // A fan from the first vertex: the books' polygons are convex (quads at most).
    for (uint32_t i = 1; i + 1 < poly.count; ++i) {
      m.triangles.push_back({{at(0), at(i), at(i + 1)}});
      m.face_materials.push_back(it->second);
    }
  }
  compute_normals(m);  // PLG files carry no normals

  Model model;
  model.path = name;
  ModelNode node;
  node.name = m.name;
  node.mesh = std::make_shared<Mesh>(std::move(m));
  model.nodes.push_back(std::move(node));
  return model;
}

}  // namespace

Model parse_plg(std::string_view text, const std::string& name, const LoadOptions& options) {
  PlgFile file = PlgParser(text, name, options).parse();
  validate(file, name);
  return build(file, name);
}

Model load_plg(const std::string& path, const LoadOptions& options) {
  std::string text = detail::read_file(path, options.max_memory);
  return parse_plg(text, path, options);
}

}  // namespace velocity
