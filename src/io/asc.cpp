// 3D Studio ASCII scene files (.asc), as written by 3D Studio R4 for DOS, the 3ds max
// "ASC" exporter and several later tools.
//
// The reader works in three steps, so no half-built model ever escapes:
//   parse    - one pass over the lines into AscFile: the records as written, numbers
//              checked (finite), face indices checked against the Tri-mesh header;
//   validate - counts in each Tri-mesh header against the records that followed, and
//              the fields every light and camera needs;
//   build    - Velocity's Model: axis conversion, materials, normals, lights, cameras.
//
// What the real files do (see shared/data/SOURCES.md) and how it is handled:
//   * LF, CRLF, lone CR and mixtures of them; no final newline; blank lines anywhere;
//   * "Page N" headers (printer pagination) anywhere, even inside vertex lists: skipped;
//   * "Tri-mesh, Vertices: N Faces: M" with any spacing; "Vertex list" / "Face list" with
//     or without a colon; an optional "Mapped" line;
//   * numbers as integers, "-0", "-0.000000", with or without a space after the colon,
//     tabs between fields; optional "U: .. V: .." on vertex lines;
//   * per-face "Material:" and "Smoothing:" lines that belong to the face just before
//     them (not sticky); material names with spaces, empty names, rgba colour codes
//     ("r255g0b0a0") and texture file names;
//   * lights ("Direct light"), cameras ("Camera (50mm)") and the ambient colour.
// Lines this reader does not know are ignored outside meshes (background, fog and
// similar scene settings), and are an error inside a mesh, where they can only mean a
// damaged or unknown dialect.
#include <algorithm>
#include <cstring>
#include <memory>
#include <unordered_map>

#include "io/read_file.hpp"
#include "io/text.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"

namespace velocity {

namespace {

using namespace detail;

constexpr uint32_t kNoMaterial = UINT32_MAX;

// "floor2.png", "Tiles.JPG": an image file name, by its extension.
bool names_image_file(std::string_view name) {
  static constexpr std::string_view kImageExtensions[] = {".png", ".jpg", ".jpeg", ".bmp", ".tga", ".gif", ".pcx"};
  for (std::string_view ext : kImageExtensions)
    if (name.size() > ext.size() && starts_with_ci(name.substr(name.size() - ext.size()), ext)) return true;
  return false;
}

// The shortest vertex and face lines a file can hold ("Vertex 0: X:0 Y:0 Z:0" is 21
// bytes, "Face 0: A:0 B:0 C:0" 19): what is left of the text bounds how many more
// records can follow, whatever a header claims, so reservations stay bounded.
constexpr size_t kMinVertexLineBytes = 20;
constexpr size_t kMinFaceLineBytes = 18;
// Bytes the finished mesh needs per vertex (position, normal, uv, and room for the
// copies compute_normals() makes along hard edges) and per face (indices, material,
// smoothing mask): used to hold a file to LoadOptions::max_memory.
constexpr size_t kBytesPerVertex = 64;
constexpr size_t kBytesPerFace = 24;

// ---------------------------------------------------------------------------------------
// Parse: the file's records, as written.

enum class ObjectKind { Unknown, Mesh, Light, Camera };

struct AscObject {
  ObjectKind kind = ObjectKind::Unknown;
  std::string name;
  uint32_t line = 0;  // the "Named object" line

  // Tri-mesh. The arrays are parallel to the file's vertex and face records.
  uint32_t header_line = 0;
  uint32_t declared_vertices = 0, declared_faces = 0;
  std::vector<Vec3> positions;
  std::vector<Vec2> uvs;  // empty, or one per vertex (zero where a vertex had none)
  std::vector<Triangle> triangles;
  std::vector<uint32_t> face_material;  // index into material_names, or kNoMaterial
  std::vector<uint32_t> smoothing;      // bit g-1 set for smoothing group g
  std::vector<std::string> material_names;
  std::unordered_map<std::string, uint32_t> material_index;
  uint32_t last_material = kNoMaterial;
  bool any_material = false;

  // Light and camera.
  bool has_position = false, has_target = false;
  Vec3 position, target;
  Vec3 color{1, 1, 1};
  float focal_mm = 0;
  float bank_degrees = 0;
};

struct AscFile {
  bool has_ambient = false;
  Vec3 ambient;
  std::vector<AscObject> objects;
  uint32_t last_line = 0;
};

class AscParser {
 public:
  AscParser(std::string_view text, const std::string& file, const LoadOptions& options)
      : lines_(text), file_(file), options_(options) {}

  AscFile parse() {
    std::string_view raw;
    while (lines_.next(raw)) parse_line(trim(raw));
    out_.last_line = lines_.number();
    return std::move(out_);
  }

 private:
  // ---- one line: the hot cases (vertex and face records) first ----
  void parse_line(std::string_view s) {
    if (s.empty()) return;
    if (starts_with_ci(s, "Vertex ") && s.size() > 7 && is_digit(s[7])) return parse_vertex(s.substr(7));
    if (starts_with_ci(s, "Face ") && s.size() > 5 && is_digit(s[5])) return parse_face(s.substr(5));
    if (starts_with_ci(s, "Material:")) return parse_material(s.substr(9));
    if (starts_with_ci(s, "Smoothing:")) return parse_smoothing(s.substr(10));
    if (is_page_header(s)) return;
    if (starts_with_ci(s, "Named object:")) return begin_object(s.substr(13));
    if (starts_with_ci(s, "Tri-mesh,")) return parse_trimesh_header(s.substr(9));
    if (starts_with_ci(s, "Vertex list") || starts_with_ci(s, "Face list") || starts_with_ci(s, "Mapped")) {
      require_mesh(s);
      return;
    }
    if (starts_with_ci(s, "Ambient light color:")) {
      out_.ambient = parse_color(s.substr(20));
      out_.has_ambient = true;
      return;
    }
    if (starts_with_ci(s, "Direct light")) return set_kind(ObjectKind::Light, s);
    if (starts_with_ci(s, "Camera")) return parse_camera_header(s.substr(6));
    if (starts_with_ci(s, "Position:")) {
      AscObject& o = light_or_camera(s);
      o.position = parse_xyz(s.substr(9));
      o.has_position = true;
      return;
    }
    if (starts_with_ci(s, "Light color:")) {
      light_or_camera(s).color = parse_color(s.substr(12));
      return;
    }
    if (starts_with_ci(s, "Target:")) {
      AscObject& o = light_or_camera(s);
      o.target = parse_xyz(s.substr(7));
      o.has_target = true;
      return;
    }
    if (starts_with_ci(s, "Bank angle:")) return parse_bank(s.substr(11));
    // A spotlight's target and cone: Velocity has no spotlights, so a spot is read as
    // a point light at its position (see build). The values are still checked.
    if (starts_with_ci(s, "Spotlight to:")) return void(parse_xyz(s.substr(13)));
    if (starts_with_ci(s, "Hotspot size:") || starts_with_ci(s, "Falloff size:")) return;
    // "Near 0 Far 1000": the camera's ranges for fog and depth cueing, not clip planes.
    if (starts_with_ci(s, "Near ") && current_is(ObjectKind::Camera)) return;
    if (current_is(ObjectKind::Mesh))
      fail_expected(file_, lines_.number(), "a Vertex, Face, Material or Smoothing line in mesh '" + current().name + "'", s);
    // Anything else outside a mesh is a scene setting Velocity has no use for
    // (background colour or image, fog, depth cueing): skipped.
  }

  // "Page 12": a printer page header that 3D Studio writes every 60 lines or so.
  static bool is_page_header(std::string_view s) {
    if (!starts_with_ci(s, "Page ")) return false;
    s = trim_left(s.substr(5));
    if (s.empty()) return false;
    for (char c : s)
      if (!is_digit(c)) return false;
    return true;
  }

  // ---- objects ----
  AscObject& current() { return out_.objects.back(); }
  bool current_is(ObjectKind kind) const { return !out_.objects.empty() && out_.objects.back().kind == kind; }

  void begin_object(std::string_view rest) {
    rest = trim(rest);
    AscObject o;
    // The name sits between the first and the last double quote; it may hold spaces.
    size_t open = rest.find('"'), close = rest.rfind('"');
    if (open != std::string_view::npos && close > open)
      o.name = std::string(rest.substr(open + 1, close - open - 1));
    else
      o.name = std::string(rest);
    o.line = lines_.number();
    out_.objects.push_back(std::move(o));
  }

  void set_kind(ObjectKind kind, std::string_view s) {
    if (out_.objects.empty() || current().kind != ObjectKind::Unknown)
      fail_expected(file_, lines_.number(), "a 'Named object:' line before this one", s);
    current().kind = kind;
  }

  void require_mesh(std::string_view s) {
    if (!current_is(ObjectKind::Mesh)) fail_expected(file_, lines_.number(), "a 'Tri-mesh' line before this one", s);
  }

  AscObject& light_or_camera(std::string_view s) {
    if (!current_is(ObjectKind::Light) && !current_is(ObjectKind::Camera))
      fail_expected(file_, lines_.number(), "a 'Direct light' or 'Camera' object before this line", s);
    return current();
  }

  // "Tri-mesh, Vertices: 8     Faces: 12"
  void parse_trimesh_header(std::string_view s) {
    std::string_view whole = s;
    set_kind(ObjectKind::Mesh, whole);
    AscObject& o = current();
    o.header_line = lines_.number();
    if (!consume_key(s, "Vertices:") || !parse_uint(s = trim_left(s), o.declared_vertices) ||
        !consume_key(s, "Faces:") || !parse_uint(s = trim_left(s), o.declared_faces) || !trim(s).empty())
      fail_expected(file_, lines_.number(), "'Tri-mesh, Vertices: N Faces: M'", whole);

    // The counts are untrusted: refuse what max_memory cannot hold, and reserve no more
    // than the rest of the text could possibly describe.
    size_t need = size_t(o.declared_vertices) * kBytesPerVertex + size_t(o.declared_faces) * kBytesPerFace;
    if (need > options_.max_memory - std::min(bytes_used_, options_.max_memory))
      fail(file_, lines_.number(),
           "mesh '" + o.name + "' declares " + std::to_string(o.declared_vertices) + " vertices and " +
               std::to_string(o.declared_faces) + " faces, more than LoadOptions::max_memory allows");
    bytes_used_ += need;
    size_t left = lines_.bytes_left();
    o.positions.reserve(std::min<size_t>(o.declared_vertices, left / kMinVertexLineBytes));
    size_t faces = std::min<size_t>(o.declared_faces, left / kMinFaceLineBytes);
    o.triangles.reserve(faces);
    o.face_material.reserve(faces);
    o.smoothing.reserve(faces);
  }

  // "12:  X: -1.5  Y:2  Z:-0  [U: 0.5  V: 1]" (after "Vertex ")
  void parse_vertex(std::string_view s) {
    std::string_view whole = s;
    if (!current_is(ObjectKind::Mesh))
      fail_expected(file_, lines_.number(), "a 'Tri-mesh' line before the first vertex", "Vertex " + std::string(whole));
    AscObject& o = current();
    uint32_t n = 0;
    parse_uint(s, n);
    size_t index = o.positions.size();
    if (n != index || !consume_key(s, ":"))
      fail_expected(file_, lines_.number(), "'Vertex " + std::to_string(index) + ":'", "Vertex " + std::string(whole));
    if (index >= o.declared_vertices)
      fail_expected(file_, lines_.number(),
                    "at most " + std::to_string(o.declared_vertices) + " vertices in mesh '" + o.name +
                        "' (its Tri-mesh header, line " + std::to_string(o.header_line) + ")",
                    "Vertex " + std::string(whole));
    Vec3 p;
    if (!key_float(s, "X:", p.x) || !key_float(s, "Y:", p.y) || !key_float(s, "Z:", p.z))
      fail_expected(file_, lines_.number(), "'X: x Y: y Z: z' with finite numbers", whole);
    o.positions.push_back(p);

    s = trim_left(s);
    if (!s.empty()) {
      Vec2 uv;
      if (!key_float(s, "U:", uv.x) || !key_float(s, "V:", uv.y) || !trim(s).empty())
        fail_expected(file_, lines_.number(), "'U: u V: v' or the end of the vertex line", s);
      if (o.uvs.empty()) o.uvs.resize(index);  // earlier vertices had none: (0, 0)
      o.uvs.push_back(uv);
    } else if (!o.uvs.empty()) {
      o.uvs.push_back({});
    }
  }

  // "12:    A:2 B:3 C:1 AB:1 BC:1 CA:1" (after "Face ")
  void parse_face(std::string_view s) {
    std::string_view whole = s;
    if (!current_is(ObjectKind::Mesh))
      fail_expected(file_, lines_.number(), "a 'Tri-mesh' line before the first face", "Face " + std::string(whole));
    AscObject& o = current();
    uint32_t n = 0;
    parse_uint(s, n);
    size_t index = o.triangles.size();
    if (n != index || !consume_key(s, ":"))
      fail_expected(file_, lines_.number(), "'Face " + std::to_string(index) + ":'", "Face " + std::string(whole));
    if (index >= o.declared_faces)
      fail_expected(file_, lines_.number(),
                    "at most " + std::to_string(o.declared_faces) + " faces in mesh '" + o.name +
                        "' (its Tri-mesh header, line " + std::to_string(o.header_line) + ")",
                    "Face " + std::string(whole));
    Triangle t;
    if (!key_uint(s, "A:", t.v[0]) || !key_uint(s, "B:", t.v[1]) || !key_uint(s, "C:", t.v[2]))
      fail_expected(file_, lines_.number(), "'A: a B: b C: c' with vertex numbers", whole);
    for (uint32_t v : t.v)
      if (v >= o.declared_vertices)
        fail_expected(file_, lines_.number(),
                      "vertex numbers below " + std::to_string(o.declared_vertices) + " (mesh '" + o.name + "')",
                      std::to_string(v));
    // Edge visibility flags: for wireframe display in 3D Studio; read and dropped.
    uint32_t flag = 0;
    while (key_uint(s, "AB:", flag) || key_uint(s, "BC:", flag) || key_uint(s, "CA:", flag)) {
    }
    if (!trim(s).empty()) fail_expected(file_, lines_.number(), "'AB: BC: CA:' edge flags or the end of the face line", s);
    o.triangles.push_back(t);
    o.face_material.push_back(kNoMaterial);
    o.smoothing.push_back(0);  // no Smoothing line: the face smooths with nothing
  }

  AscObject& mesh_with_a_face(std::string_view what, std::string_view s) {
    if (!current_is(ObjectKind::Mesh) || current().triangles.empty())
      fail_expected(file_, lines_.number(), "a Face line before this " + std::string(what) + " line", s);
    return current();
  }

  // Material:"NAME" or Material: "NAME": applies to the face just before.
  void parse_material(std::string_view s) {
    AscObject& o = mesh_with_a_face("Material", s);
    s = trim(s);
    size_t open = s.find('"'), close = s.rfind('"');
    std::string_view name = open != std::string_view::npos && close > open ? s.substr(open + 1, close - open - 1) : s;
    // Runs of faces share a material: try the last one before hashing.
    uint32_t index = o.last_material;
    if (index == kNoMaterial || o.material_names[index] != name) {
      auto [it, added] = o.material_index.try_emplace(std::string(name), uint32_t(o.material_names.size()));
      if (added) o.material_names.emplace_back(name);
      index = o.last_material = it->second;
    }
    o.face_material.back() = index;
    o.any_material = true;
  }

  // Smoothing:  1, 2  -> bits 0 and 1. Groups are numbered 1 to 32.
  void parse_smoothing(std::string_view s) {
    AscObject& o = mesh_with_a_face("Smoothing", s);
    uint32_t mask = 0;
    for (;;) {
      s = trim_left(s);
      while (!s.empty() && s[0] == ',') s = trim_left(s.substr(1));
      if (s.empty()) break;
      uint32_t group = 0;
      if (!parse_uint(s, group) || group < 1 || group > 32)
        fail_expected(file_, lines_.number(), "smoothing group numbers from 1 to 32", s);
      mask |= 1u << (group - 1);
    }
    o.smoothing.back() = mask;
  }

  // "Camera (50.000004mm)": the lens's focal length.
  void parse_camera_header(std::string_view s) {
    std::string_view whole = s;
    set_kind(ObjectKind::Camera, whole);
    float focal = 0;
    if (!consume_key(s, "(") || !parse_float(s = trim_left(s), focal) || !consume_key(s, "mm") ||
        !consume_key(s, ")") || !(focal > 0))
      fail_expected(file_, lines_.number(), "'Camera (F mm)' with a focal length above 0", "Camera" + std::string(whole));
    current().focal_mm = focal;
  }

  // "Bank angle: 0 degrees": the camera's roll about its line of sight.
  void parse_bank(std::string_view s) {
    std::string_view whole = s;
    if (!current_is(ObjectKind::Camera)) fail_expected(file_, lines_.number(), "a Camera object before 'Bank angle'", s);
    float degrees = 0;
    if (!parse_float(s = trim_left(s), degrees) || !(consume_key(s, "degrees") || trim(s).empty()))
      fail_expected(file_, lines_.number(), "'Bank angle: N degrees'", whole);
    current().bank_degrees = degrees;
  }

  // "X: 1 Y: 2 Z: 3" (Position, Target, Spotlight to)
  Vec3 parse_xyz(std::string_view s) {
    std::string_view whole = s;
    Vec3 p;
    if (!key_float(s, "X:", p.x) || !key_float(s, "Y:", p.y) || !key_float(s, "Z:", p.z) || !trim(s).empty())
      fail_expected(file_, lines_.number(), "'X: x Y: y Z: z' with finite numbers", whole);
    return p;
  }

  // "Red=0.3 Green=0.3 Blue=0.3"
  Vec3 parse_color(std::string_view s) {
    std::string_view whole = s;
    Vec3 c;
    if (!key_float(s, "Red=", c.x) || !key_float(s, "Green=", c.y) || !key_float(s, "Blue=", c.z) ||
        !trim(s).empty())
      fail_expected(file_, lines_.number(), "'Red=r Green=g Blue=b' with finite numbers", whole);
    return c;
  }

  static bool key_float(std::string_view& s, std::string_view key, float& out) {
    if (!consume_key(s, key)) return false;
    s = trim_left(s);
    return parse_float(s, out);
  }
  static bool key_uint(std::string_view& s, std::string_view key, uint32_t& out) {
    std::string_view t = s;
    if (!consume_key(t, key)) return false;
    t = trim_left(t);
    if (!parse_uint(t, out)) return false;
    s = t;
    return true;
  }

  LineReader lines_;
  const std::string& file_;
  const LoadOptions& options_;
  AscFile out_;
  size_t bytes_used_ = 0;
};

// ---------------------------------------------------------------------------------------
// Validate: what the parse could not check line by line.

void validate(const AscFile& f, const std::string& file) {
  if (f.objects.empty())
    fail(file, std::max<uint32_t>(f.last_line, 1),
         "expected at least one 'Named object:' (is this a 3D Studio ASCII file?), got none");
  for (const AscObject& o : f.objects) {
    switch (o.kind) {
      case ObjectKind::Mesh:
        if (o.positions.size() != o.declared_vertices)
          fail(file, o.header_line,
               "expected " + std::to_string(o.declared_vertices) + " vertices in mesh '" + o.name +
                   "' (its Tri-mesh header), got " + std::to_string(o.positions.size()));
        if (o.triangles.size() != o.declared_faces)
          fail(file, o.header_line,
               "expected " + std::to_string(o.declared_faces) + " faces in mesh '" + o.name +
                   "' (its Tri-mesh header), got " + std::to_string(o.triangles.size()));
        break;
      case ObjectKind::Light:
        if (!o.has_position) fail(file, o.line, "expected a 'Position:' line for light '" + o.name + "', got none");
        break;
      case ObjectKind::Camera:
        if (!o.has_position || !o.has_target)
          fail(file, o.line, "expected 'Position:' and 'Target:' lines for camera '" + o.name + "', got " +
                                 (o.has_position ? "no Target" : "no Position"));
        break;
      case ObjectKind::Unknown:
        break;  // a named object of a kind Velocity does not read (none seen so far)
    }
  }
}

// ---------------------------------------------------------------------------------------
// Build: Velocity's model.

// 3D Studio is right-handed with Z up; Velocity is right-handed with Y up. The rotation
// of -90 degrees about X, (x, y, z) -> (x, z, -y), stands models upright, keeps their
// handedness (no mirror image) and so keeps every counter-clockwise front face front
// facing; 3D Studio's front view (looking along +Y) becomes Velocity's default view
// (looking along -Z). See LoadOptions::swap_yz.
Vec3 to_velocity(Vec3 p, bool swap_yz) { return swap_yz ? Vec3{p.x, p.z, -p.y} : p; }

// "r133g169b191a0" -> (133, 169, 191) / 255. Alpha (written as 0 or 255 by different
// tools, so its meaning is unclear) is read and ignored.
bool parse_color_code(std::string_view name, Vec3& color) {
  int rgb[3];
  const char keys[3] = {'r', 'g', 'b'};
  std::string_view s = name;
  for (int i = 0; i < 3; ++i) {
    uint32_t v = 0;
    if (s.empty() || to_lower(s[0]) != keys[i]) return false;
    s.remove_prefix(1);
    if (!parse_uint(s, v) || v > 255) return false;
    rgb[i] = int(v);
  }
  if (!s.empty()) {
    uint32_t a = 0;
    if (to_lower(s[0]) != 'a') return false;
    s.remove_prefix(1);
    if (!parse_uint(s, a) || a > 255 || !s.empty()) return false;
  }
  color = Vec3{float(rgb[0]), float(rgb[1]), float(rgb[2])} / 255.0f;
  return true;
}

Mesh build_mesh(AscObject& o, bool swap_yz) {
  Mesh m;
  m.name = o.name;
  m.positions = std::move(o.positions);
  for (Vec3& p : m.positions) p = to_velocity(p, swap_yz);
  // 3D Studio's V is 0 at the image's bottom row, the engine's at the top: the one
  // place ASC's uvs are converted (v' = 1 - v; a vertex without uvs keeps (0, 0)'s).
  m.uvs = std::move(o.uvs);
  for (Vec2& uv : m.uvs) uv.y = 1 - uv.y;
  m.triangles = std::move(o.triangles);

  if (o.any_material) {
    // Faces without a Material line get an unnamed default material.
    uint32_t unnamed = kNoMaterial;
    for (uint32_t& fm : o.face_material)
      if (fm == kNoMaterial) {
        if (unnamed == kNoMaterial) {
          auto [it, added] = o.material_index.try_emplace("", uint32_t(o.material_names.size()));
          if (added) o.material_names.emplace_back();
          unnamed = it->second;
        }
        fm = unnamed;
      }
    for (std::string& name : o.material_names) {
      Material mat;
      parse_color_code(name, mat.color);
      // Any other name (a 3D Studio library material, a texture file such as
      // "floor2.png") is kept in the name; the colour stays the default grey. A name
      // that is an image file is the material's texture (pinball exports write them).
      if (names_image_file(name)) mat.texture_file = name;
      mat.name = std::move(name);
      m.materials.push_back(std::move(mat));
    }
    m.face_materials = std::move(o.face_material);
  }

  // Every face that shares one and the same group smooths with all of its neighbours:
  // that is what an empty mask list means, and compute_normals() has a faster path for it.
  // Otherwise the masks go in as they are; faces without a group stay faceted, as in
  // 3D Studio.
  bool uniform = !o.smoothing.empty() && o.smoothing[0] != 0 &&
                 std::all_of(o.smoothing.begin(), o.smoothing.end(), [&](uint32_t g) { return g == o.smoothing[0]; });
  if (!uniform) m.smoothing_groups = std::move(o.smoothing);

  compute_normals(m);  // ASC files carry no normals
  return m;
}

// Near and far planes for a camera that sees the meshes inside `scene`: 3D Studio keeps
// no clip planes (its Near/Far are ranges for fog), so they are fitted to the model.
void fit_clip_planes(Camera& camera, Sphere scene) {
  if (scene.radius <= 0) return;
  float d = length(camera.position - scene.center);
  float r = scene.radius * 1.01f;
  camera.far = d + r;
  camera.near = std::max(d - r, camera.far * 1e-3f);
}

Sphere bounds_of(const Model& model) {
  Bounds box;
  bool any = false;
  for (const ModelNode& n : model.nodes)
    if (n.mesh && !n.mesh->positions.empty()) {
      Bounds b = n.mesh->bounds();
      if (!any) box = b, any = true;
      box.min = {std::min(box.min.x, b.min.x), std::min(box.min.y, b.min.y), std::min(box.min.z, b.min.z)};
      box.max = {std::max(box.max.x, b.max.x), std::max(box.max.y, b.max.y), std::max(box.max.z, b.max.z)};
    }
  if (!any) return {};
  return {box.center(), length(box.max - box.min) / 2};
}

Model build(AscFile& f, const std::string& name, const LoadOptions& options) {
  Model model;
  model.path = name;
  if (f.has_ambient) model.lights.push_back(Light::ambient(f.ambient));
  for (AscObject& o : f.objects) {
    switch (o.kind) {
      case ObjectKind::Mesh: {
        ModelNode node;
        node.name = o.name;
        node.mesh = std::make_shared<Mesh>(build_mesh(o, options.swap_yz));
        model.nodes.push_back(std::move(node));
        break;
      }
      case ObjectKind::Light:
        // 3D Studio's "Direct light" is its one light object: an omni light shining from
        // its position in all directions (a spotlight adds a target and a cone), with no
        // fall-off by default. So it becomes a point light without attenuation, not a
        // directional light.
        model.lights.push_back(Light::point(to_velocity(o.position, options.swap_yz), o.color));
        break;
      case ObjectKind::Camera: {
        NamedCamera c;
        c.name = o.name;
        c.camera.position = to_velocity(o.position, options.swap_yz);
        c.camera.fov_y = Camera::fov_from_focal_length(o.focal_mm);
        c.camera.look_at(to_velocity(o.target, options.swap_yz));
        // Bank turns the camera about its line of sight; taken as Velocity's roll with
        // the same sign (every sample file has 0, so the sign is unconfirmed).
        c.camera.roll = radians(o.bank_degrees);
        model.cameras.push_back(std::move(c));
        break;
      }
      case ObjectKind::Unknown:
        break;
    }
  }
  Sphere scene = bounds_of(model);
  for (NamedCamera& c : model.cameras) fit_clip_planes(c.camera, scene);
  return model;
}

}  // namespace

Model parse_asc(std::string_view text, const std::string& name, const LoadOptions& options) {
  AscFile file = AscParser(text, name, options).parse();
  validate(file, name);
  return build(file, name, options);
}

Model load_asc(const std::string& path, const LoadOptions& options) {
  std::string text = detail::read_file(path, options.max_memory);
  return parse_asc(text, path, options);
}

}  // namespace velocity
